#pragma once
// One robot of the paper's scheme: its real generator (its position), its virtual generator
// (where it would be if there were no obstacles), and the two targets.
#include <cstdint>
#include <memory>
#include <optional>

#include "planners/planner.hpp"
#include "robot/kinematics.hpp"

namespace covsim {

struct Robot {
  std::uint32_t id = 0;
  Vec2 position;           // g_real
  Vec2 virtual_generator;  // g_virt
  Vec2 virtual_target;     // t_virt: the target loop 1 last set
  Vec2 real_target;        // t_real: t_virt, or its projection onto Ω
  bool projected = false;  // t_virt lies outside Ω (an obstacle boundary Voronoi region)
  bool stable = false;     // the last loop 1 left it where it was: nothing to do
  Vec2 goal;               // the goal the planner is working on
  Vec2 planner_goal;       // the goal as the planner was given it (in its odometry's frame)
  Vec2 assigned;           // the loop-1 target that goal was set for
  // Failure measures: loop-2 steps taken while the loop-1 target lay outside Ω, and the
  // time spent stalled (the planner gave up short of its goal).
  std::uint64_t target_outside_steps = 0;
  double stalled_time = 0.0;
  PlanStatus status = PlanStatus::reached;
  // With collision avoidance: the planner's step not yet reached (the robot follows it over
  // as many motion steps as its neighbours allow; its status applies once there), the
  // velocity of the last motion step, how long it has been blocked short of the waypoint,
  // and whether that has become a deadlock (until it reaches a planner step again).
  std::optional<PlanStep> waypoint;
  Vec2 waypoint_from;      // where the robot was when its planner proposed the waypoint
  bool displaced = false;  // it took the last step on the way only nearly (a detour)
  Vec2 velocity;
  double blocked_time = 0.0;
  bool deadlocked = false;
  // Its body's heading and speeds (kinematics other than the single integrator), and the
  // point it is driving toward.
  BodyState body;
  Vec2 driving_to;
  // Stepping aside for another robot, to this point, for at most this many more seconds.
  double give_way = 0.0;
  Vec2 give_way_to;
  double path_length = 0.0;
  std::unique_ptr<Planner> planner;
};

}  // namespace covsim
