#pragma once
// A potential-field planner over what the range sensor sees (Khatib, 1986). The robot
// descends U = U_att + U_rep: a conic attractive potential (a unit pull toward the goal)
// and, for every sensed boundary piece closer than the influence distance d0, Khatib's
// repulsive potential ½ η (1/d - 1/d0)², whose push is η (1/d - 1/d0) / d² away from the
// piece's closest point. η is `repulsive_gain` d0³ / 48, so with the default gain of 1 a wall
// at d0 / 4 pushes as hard as the goal pulls; within d0 of the goal the push is scaled by
// (dg / d0)² (Ge and Cui's fix for goals next to obstacles). Against a wall it touches, the robot
// slides: the part of the step into the wall is removed. Within the influence distance of a goal it
// sees in a straight line it drives straight there (so a goal on a wall can be reached).
//
// With planner.map "sensed" it never consults Ω: the final approach needs a line of sight
// its reading shows clear, and a step that would cross a wall it senses stops at that wall.
// On the given map (the default when Ω is known) it asks Ω for both, as before.
//
// Like every gradient method it can stop in a local minimum (a cup, a goal inside an
// obstacle): when the distance to the goal has not fallen below its best by `progress`
// within `stall_window` steps, it reports `stalled`; the coverage controller then treats
// the goal as unreachable and sends the robot to its projection.
#include <cstddef>

#include "geometry/environment.hpp"
#include "planners/planner.hpp"
#include "planners/planner_entry.hpp"

namespace covsim {

struct PotentialFieldParams {
  double influence = 0.1;         // d0, metres
  double repulsive_gain = 1.0;    // η in units of d0³ / 48
  std::size_t stall_window = 50;  // steps
  double progress = 1e-3;         // metres: the least gain that counts within a window
  bool sensed = false;            // planner.map "sensed": Ω is never consulted
  bool noisy = false;             // its readings carry range or position noise
  // influence a tenth of Ω's bounding-box diameter, progress 1e-3 of it.
  static PotentialFieldParams for_environment(double diameter);
};

class PotentialField final : public Planner {
 public:
  PotentialField(const Environment& env, PotentialFieldParams params) : env_(env), p_(params) {}
  std::string_view name() const override { return "potential_field"; }
  void set_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;
  // The direction of steepest descent at the reading (not normalised; for tests).
  Vec2 force(const SensorReading& reading) const;

 private:
  const Environment& env_;
  PotentialFieldParams p_;
  Vec2 goal_;
  PlanStatus status_ = PlanStatus::reached;
  double best_ = 0.0;           // least distance to the goal so far
  std::size_t since_best_ = 0;  // steps since it last fell by `progress`
};

PlannerEntry potential_field_entry();

}  // namespace covsim
