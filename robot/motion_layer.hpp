#pragma once
// How a robot's body carries out its planner's steps (the motion layer). Without kinematics
// or collision avoidance, at once: the controller moves the robot to the step. With either,
// the step becomes a waypoint the body follows over as many motion steps as its kinematics
// (kinematics.hpp) and its neighbours (collision_avoidance.hpp) allow; a robot blocked short
// of its waypoint by its neighbours for kDeadlockTime is deadlocked until it reaches a
// planner step again, and of two robots in each other's way one gives way (steps aside, then
// returns to its goal).
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/kernel.hpp"
#include "geometry/environment.hpp"
#include "robot/collision_avoidance.hpp"
#include "robot/coverage_config.hpp"
#include "robot/robot.hpp"

namespace covsim {

class ReceiverGrid;

// What the motion layer asks of the controller.
struct MotionHost {
  // The robot moves to a motion step's end.
  std::function<void(Robot&, Vec2)> move_to;
  // The robot is at its planner's step, which ended with this status; false: the run stops.
  std::function<bool(Robot&, PlanStatus)> arrive;
  // Its planner starts afresh from where the robot is, for the same goal.
  std::function<void(Robot&)> restart;
  // Robot i's free space.
  std::function<const Environment&(std::uint32_t)> free_space;
};

class MotionLayer {
 public:
  // `robots` outlives the layer and keeps its size; `env` is Ω (neighbours in sight).
  MotionLayer(const Kernel& kernel, const Environment& env, const CoverageConfig& config,
              std::vector<Robot>& robots, MotionHost host);
  ~MotionLayer();

  // Whether a planner's step is a waypoint followed over motion steps (with kinematics or
  // collision avoidance), rather than reached at once.
  bool follows_waypoints() const { return avoidance_ || kinematics_; }
  bool avoids_collisions() const { return avoidance_ != nullptr; }
  // A motion step toward r's waypoint; false: the run stops.
  bool follow_waypoint(Robot& r);
  // A motion step aside for the robot it makes room for; then it returns to its goal.
  void give_way(Robot& r);
  // Robot r moved to p (the neighbours near a point).
  void moved(const Robot& r, Vec2 p);

  static constexpr double kDeadlockTime = 1.0;  // s
  std::uint64_t deadlocks() const { return deadlocks_; }
  double deadlock_time() const { return deadlock_time_; }
  std::uint64_t deadlocks_resolved() const { return deadlocks_resolved_; }
  std::uint64_t give_ways() const { return give_ways_; }
  double turn_time() const { return turn_time_; }
  std::uint64_t hard_stops() const { return hard_stops_; }

 private:
  bool arrive_at_waypoint(Robot& r);
  // The body's motion toward `to` in one motion step (at once without kinematics): where it
  // gets to.
  Vec2 drive(Robot& r, Vec2 to);
  // Calls f with every robot that may lie within radius of p (a superset), in index order.
  template <class F>
  void for_each_near(Vec2 p, double radius, F&& f) const;
  // What robot r senses of its neighbours, into neighbors_.
  void sense_neighbors(const Robot& r);
  // The avoidance's velocity for robot r from what it senses; throws for one that is not
  // finite or faster than max_speed.
  Vec2 avoiding_velocity(const Robot& r, Vec2 preferred, double max_speed);
  // A robot deadlocked for a while: replanned, or one of the two in each other's way (the
  // larger id, or a settled robot on the waypoint) gives way.
  void resolve(Robot& r);
  // Robot r steps aside for a robot at `from`; false (and nothing started) when the walls and
  // the other bodies leave it no room.
  bool start_giving_way(Robot& r, Vec2 from);
  // The largest fraction of the straight motion from r's position to `to` that brings its
  // body no nearer to another's than touching (or than it already is).
  double clear_fraction(const Robot& r, Vec2 to) const;

  const Kernel& kernel_;
  const Environment& env_;
  const CoverageConfig& config_;
  std::vector<Robot>& robots_;
  MotionHost host_;
  std::unique_ptr<CollisionAvoidance> avoidance_;  // unset: none
  std::unique_ptr<Kinematics> kinematics_;         // unset: the single integrator
  std::vector<SensedNeighbor> neighbors_;
  std::unique_ptr<ReceiverGrid> near_;  // with avoidance: the robots near a point
  double near_range_ = 0.0;
  mutable std::vector<std::uint32_t> near_ids_;
  std::uint64_t deadlocks_ = 0, deadlocks_resolved_ = 0, give_ways_ = 0;
  double deadlock_time_ = 0.0;
  double turn_time_ = 0.0;
  std::uint64_t hard_stops_ = 0;
};

}  // namespace covsim
