#include "planners/no_planner.hpp"

namespace covsim {

void NoPlanner::set_goal(Vec2 goal) {
  goal_ = goal;
  status_ = PlanStatus::moving;
}

PlanStep NoPlanner::step(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (status_ != PlanStatus::moving) return PlanStep{x, status_};
  const double d = distance(x, goal_);
  if (d <= max_step) {
    status_ = PlanStatus::reached;
    return PlanStep{goal_, status_};
  }
  return PlanStep{x + (max_step / d) * (goal_ - x), status_};
}

PlannerEntry no_planner_entry() {
  PlannerEntry e;
  e.name = "none";
  e.description =
      "no planner: straight at the target through whatever is in the way (the paper's "
      "Section II baselines); a motion that leaves Ω ends the run";
  e.make = [](const PlannerContext&, const Params&) -> PlannerSource {
    return [] { return std::make_unique<NoPlanner>(); };
  };
  return e;
}

}  // namespace covsim
