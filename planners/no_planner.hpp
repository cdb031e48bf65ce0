#pragma once
// No local planner: the robot drives straight at its goal whatever lies in the way, as the
// controllers of the paper's Section II do (Fig. 2: "the robot happens to leave the region").
// It is the baseline that shows why the method needs a planner: its motion may leave Ω, and
// the controller then ends the run (stop reason `left_environment`) where it would leave.
// It reports `reached` at the goal and is `moving` until then.
#include "planners/planner.hpp"
#include "planners/planner_entry.hpp"

namespace covsim {

class NoPlanner final : public Planner {
 public:
  std::string_view name() const override { return "none"; }
  bool avoids_obstacles() const override { return false; }
  void set_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;

 private:
  Vec2 goal_;
  PlanStatus status_ = PlanStatus::reached;
};

PlannerEntry no_planner_entry();

}  // namespace covsim
