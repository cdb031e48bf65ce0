#pragma once
// Reciprocal collision avoidance between robots with bodies: the layer between the planner's
// step and the motion. Each motion step it turns the velocity that would take the robot to
// its planner's waypoint into one that keeps its body clear of its neighbours', from what it
// senses of them (their positions and the velocities of their last motion steps, within
// range()). An extension point: an avoidance is this interface plus one entry in
// collision_avoidance_registry(). The controller keeps the waypoint whole (the planner's path
// is followed, only later) and never lets a motion bring two bodies nearer than touching.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/registry.hpp"
#include "core/vec2.hpp"

namespace covsim {

// A neighbour as a robot senses it.
struct SensedNeighbor {
  Vec2 position;
  Vec2 velocity;  // over its last motion step, m/s
};

struct AvoidanceQuery {
  Vec2 position;
  Vec2 velocity;   // the robot's own over its last motion step
  Vec2 preferred;  // to the waypoint in one motion step
  double radius = 0.0;
  double max_speed = 0.0;
  double step_time = 0.0;  // s, a motion step
  const std::vector<SensedNeighbor>& neighbors;
};

class CollisionAvoidance {
 public:
  virtual ~CollisionAvoidance() = default;
  // The velocity of this motion step, at most max_speed; `preferred` itself (bit for bit)
  // when nothing needs avoiding.
  virtual Vec2 velocity(const AvoidanceQuery& q) = 0;
  // How far it senses neighbours, m, for robots of this radius, top speed and motion step
  // (0: it needs none).
  virtual double range(double radius, double max_speed, double step_time) const = 0;
};

using AvoidanceEntry = Component<std::function<std::unique_ptr<CollisionAvoidance>(const Params&)>>;

// A scenario's "robots": {"avoidance": {"type": NAME, ...}}.
struct AvoidanceConfig {
  std::string type = "none";
  Params params;
};

}  // namespace covsim
