#include "robot/planning_layer.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "robot/guarded_call.hpp"
#include "robot/mapping.hpp"

namespace covsim {

PlanningLayer::PlanningLayer(const Kernel& kernel, BeliefLayer& belief, SensorModel& sensor,
                             double step, double radius, const ConfigurationSpace& space,
                             const std::vector<std::size_t>& part, const PlannerSpace& planners)
    : kernel_(kernel),
      belief_(belief),
      sensor_(sensor),
      step_(step),
      radius_(radius),
      space_(space),
      part_(part),
      planners_(planners) {}

void PlanningLayer::set_goal(Robot& r, Vec2 goal) {
  r.goal = goal;
  r.planner_goal = belief_.in_planner_frame(r, goal);
  guarded_call(r.id, "planner", r.planner->name(), kernel_.now(),
               [&] { r.planner->set_goal(r.planner_goal); });
  r.status = PlanStatus::moving;
}

void PlanningLayer::move_goal(Robot& r, Vec2 goal) {
  r.goal = goal;
  r.planner_goal = belief_.in_planner_frame(r, goal);
  guarded_call(r.id, "planner", r.planner->name(), kernel_.now(),
               [&] { r.planner->move_goal(r.planner_goal); });
}

PlanStep PlanningLayer::step(Robot& r) {
  // The planner works in its frame: from where it believes the robot is, the walls where it
  // senses them from there.
  Vec2 known = belief_.planner_position(r);
  // On Ω's map, from the estimate taken into the inflated free space (a robot within the
  // inflation of a wall plans from its edge).
  if (belief_.map_frame()) {
    const Environment& e = planners_.of(r.id);
    if (!e.contains(known)) known = e.closest_point(known);
  }
  const bool exact = known == r.position;
  const PlanStep s = guarded_call(r.id, "planner", r.planner->name(), kernel_.now(), [&] {
    SensorReading reading = sensor_.reading(r.id, r.position);
    if (!exact) shift(reading, known - r.position);
    const PlanStep step = r.planner->step(reading, step_);
    if (!is_finite(step.next))
      throw std::invalid_argument(
          fmt::format("a step must be a finite point, found ({}, {})", step.next.x, step.next.y));
    return step;
  });
  // A robot moves at most its step length per planner step, whatever the planner asks (up to
  // the rounding of the positions compared, which a tiny step may not exceed relatively).
  if (!(distance(known, s.next) <= step_ * (1.0 + 1e-9) + distance_rounding(known, s.next))) {
    throw std::runtime_error(fmt::format(
        "robot {}'s planner {} proposed a step of {} m at t={} s; the step length is {} m", r.id,
        r.planner->name(), distance(known, s.next), kernel_.now().seconds(), step_));
  }
  // The same displacement from where the robot really is.
  return exact ? s : PlanStep{r.position + (s.next - known), s.status};
}

void PlanningLayer::learn(Robot& r, const Scan& scan) {
  std::vector<SensedPiece> walls;
  if (radius_ == 0.0) {
    for (const VisiblePiece& p : scan.pieces)
      walls.push_back(SensedPiece{p.a, p.b});
  } else {
    // Bodies plan in Ω shrunk by their radius, whose walls the reading's walls determine: the
    // receiver takes them as seen from where the reading was taken (the whole reading's,
    // though a message may have carried part of it), when that lies in its part of the
    // free space.
    const auto k = space_.part_of(scan.origin);
    if (!k || *k != part_[r.id]) return;
    const SensorReading seen = sense(free_space(r.id), scan.origin, scan.range);
    walls = seen.visible().pieces;
  }
  guarded_call(r.id, "planner", r.planner->name(), kernel_.now(), [&] { r.planner->learn(walls); });
}

}  // namespace covsim
