#include "planners/planner_run.hpp"

namespace covsim {

PlannerRun run_planner(const Environment& env, Planner& planner, Vec2 start, Vec2 goal,
                       double range, double step_length, std::size_t max_steps) {
  PlannerRun run;
  run.path.push_back(start);
  planner.set_goal(goal);
  Vec2 x = start;
  for (; run.steps < max_steps; ++run.steps) {
    const PlanStep s = planner.step(sense(env, x, range), step_length);
    const Vec2 next = env.advance(x, s.next);
    run.length += distance(x, next);
    if (!(next == x)) run.path.push_back(next);
    x = next;
    if (is_settled(s.status)) {
      run.status = s.status;
      break;
    }
  }
  return run;
}

}  // namespace covsim
