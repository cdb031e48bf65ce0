#include "planners/straight_line.hpp"

namespace covsim {

void StraightLine::set_goal(Vec2 goal) {
  goal_ = goal;
  status_ = PlanStatus::moving;
}

PlanStep StraightLine::step(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (status_ != PlanStatus::moving) return PlanStep{x, status_};
  const double d = distance(x, goal_);
  if (d <= (stops_at_walls_ ? env_.tolerance() : max_step)) {
    status_ = PlanStatus::reached;
    return PlanStep{goal_, status_};
  }
  const Vec2 want = d <= max_step ? goal_ : x + (max_step / d) * (goal_ - x);
  if (!stops_at_walls_) return PlanStep{want, status_};
  const Vec2 next = env_.advance(x, want);
  // A wall in the way: stop at it (the step that reaches the wall still moves).
  if (distance(next, x) <= env_.tolerance()) status_ = PlanStatus::stalled;
  if (next == goal_) status_ = PlanStatus::reached;
  return PlanStep{next, status_};
}

PlannerEntry straight_line_entry() {
  PlannerEntry e;
  e.name = "straight_line";
  e.description = "straight at the target; stops at the first wall (contact only)";
  e.blind = true;
  e.make = [](const PlannerContext& ctx, const Params&) -> PlannerSource {
    const Environment* env = &ctx.environment;
    return [env] { return std::make_unique<StraightLine>(*env); };
  };
  return e;
}

PlannerEntry no_planner_entry() {
  PlannerEntry e;
  e.name = "none";
  e.description =
      "no planner: straight at the target through whatever is in the way (the paper's "
      "Section II baselines); a motion that leaves Ω ends the run";
  e.blind = true;
  e.make = [](const PlannerContext& ctx, const Params&) -> PlannerSource {
    const Environment* env = &ctx.environment;
    return [env] { return std::make_unique<StraightLine>(*env, false); };
  };
  return e;
}

}  // namespace covsim
