#pragma once
// The naive baseline: straight at the goal, stopping where the motion would enter an
// obstacle. It reports `reached` at the goal and `stalled` once pressed against a wall that
// blocks the way (a goal inside an obstacle always ends so). Never leaves Ω.
#include "core/geometry/environment.hpp"
#include "planners/planner.hpp"
#include "planners/planner_entry.hpp"

namespace covsim {

class StraightLine final : public Planner {
 public:
  explicit StraightLine(const Environment& env) : env_(env) {}
  std::string_view name() const override { return "straight_line"; }
  void set_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;

 private:
  const Environment& env_;
  Vec2 goal_;
  PlanStatus status_ = PlanStatus::reached;
};

PlannerEntry straight_line_entry();

}  // namespace covsim
