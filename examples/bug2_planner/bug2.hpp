#pragma once
// Bug2 (Lumelsky and Stepanov, 1987) with a contact sensor, as a covsim planner built outside
// covsim's source tree: straight along the m-line (start to goal) until a wall faces the goal,
// then along that wall until the m-line is met again closer to the goal than where the wall
// was hit, with the way to the goal free. Back where the wall was hit: the goal is
// unreachable if that obstacle, now walked round, encloses it; the robot then walks to the
// obstacle's point closest to the goal (the projection) and reports `projected`.
#include <optional>
#include <vector>

#include "planners/planner_entry.hpp"
#include "planners/recorded_obstacle.hpp"

namespace example {

class Bug2 final : public covsim::Planner {
 public:
  explicit Bug2(double tolerance) : tolerance_(tolerance) {}
  std::string_view name() const override { return "bug2"; }
  void set_goal(covsim::Vec2 goal) override;
  covsim::PlanStep step(const covsim::SensorReading& r, double max_step) override;

 private:
  enum class Mode { line, follow, to_projection, done };
  covsim::PlanStep walk(const covsim::SensorReading& r, double max_step,
                        std::optional<covsim::Vec2> stop);
  covsim::PlanStep finish(covsim::Vec2 at, covsim::PlanStatus s);

  double tolerance_;
  covsim::Vec2 goal_, start_, hit_;
  std::optional<covsim::Vec2> line_start_;  // the m-line runs from here to the goal
  Mode mode_ = Mode::done;
  covsim::PlanStatus status_ = covsim::PlanStatus::reached;
  double walked_ = 0.0;
  std::vector<covsim::Vec2> walked_points_;  // its positions along the wall, the obstacle
  std::optional<covsim::RecordedObstacle> obstacle_;
  covsim::RingPlace target_;
};

// Its registry entry: name "bug2", no parameters.
covsim::PlannerEntry bug2_entry();

}  // namespace example
