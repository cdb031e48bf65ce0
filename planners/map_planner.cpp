#include "planners/map_planner.hpp"

namespace covsim {

void MapPlanner::set_goal(Vec2 goal) {
  goal_ = goal;
  planned_ = false;
  status_ = PlanStatus::moving;
  follower_.clear();
}

PlanStep MapPlanner::step(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (status_ != PlanStatus::moving) return PlanStep{x, status_};
  if (!planned_) {
    planned_ = true;
    Vec2 target = goal_;
    arrival_ = PlanStatus::reached;
    if (!env_.contains(goal_)) {
      const auto component = env_.component_of(x);
      target = component ? env_.closest_point(goal_, *component) : env_.closest_point(goal_);
      arrival_ = PlanStatus::projected;
    }
    std::optional<std::vector<Vec2>> path = plan(x, target);
    if (!path) {
      status_ = PlanStatus::stalled;
      return PlanStep{x, status_};
    }
    follower_.assign(std::move(*path));
  }
  const Vec2 next = follower_.advance(x, max_step, env_.tolerance());
  if (follower_.done()) status_ = arrival_;
  return PlanStep{next, status_};
}

}  // namespace covsim
