#pragma once
// The naive baselines: straight at the goal.
// - `straight_line` stops where the motion would enter an obstacle: it reports `reached` at
//   the goal and `stalled` once pressed against a wall that blocks the way (a goal inside an
//   obstacle always ends so). Never leaves Ω.
// - `none`, no planner at all, drives on through whatever is in the way, as the controllers
//   of the paper's Section II do (Fig. 2d: "the robot happens to leave the region"): its
//   motion may leave Ω, and the controller then ends the run where it would leave (stop
//   reason `left_environment`). It reports `reached` at the goal and is `moving` until then.
#include "geometry/environment.hpp"
#include "planners/planner.hpp"
#include "planners/planner_entry.hpp"

namespace covsim {

class StraightLine final : public Planner {
 public:
  // stops_at_walls false: the `none` planner.
  explicit StraightLine(const Environment& env, bool stops_at_walls = true)
      : env_(env), stops_at_walls_(stops_at_walls) {}
  std::string_view name() const override { return stops_at_walls_ ? "straight_line" : "none"; }
  bool avoids_obstacles() const override { return stops_at_walls_; }
  void set_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;

 private:
  const Environment& env_;
  bool stops_at_walls_;
  Vec2 goal_;
  PlanStatus status_ = PlanStatus::reached;
};

PlannerEntry straight_line_entry();
PlannerEntry no_planner_entry();

}  // namespace covsim
