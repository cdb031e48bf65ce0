#pragma once
// How a robot's body moves: the layer that carries out the planner's steps (after collision
// avoidance, if any). An extension point: a kinematics is this interface plus one entry in
// kinematics_registry(). `single_integrator` (the default, the paper's) moves straight to
// the step at once and is never called; the others have a heading and carry out each motion
// by turning in place toward the point and then driving straight to it, within their speed and
// acceleration limits, so that the body stays on the planner's path (a polyline in the free
// space) and turning costs time.
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "core/registry.hpp"
#include "core/vec2.hpp"

namespace covsim {

// What the body is doing: its heading and its speeds (the turn rate while turning in place).
struct BodyState {
  double heading = 0.0;    // rad, counter-clockwise from +x
  double speed = 0.0;      // m/s, along the heading (never backwards)
  double turn_rate = 0.0;  // rad/s, counter-clockwise
};

struct BodyMotion {
  Vec2 position;  // on the segment from where it was toward the point, the point itself on arrival
  BodyState state;
  bool arrived = false;
  // The point moved while the body drove toward another one faster than it could stop for
  // it: it stopped at once (only collision avoidance's detours move it).
  bool hard_stop = false;
  double turning = 0.0;  // s of the motion spent turning in place
};

// The limits the motion keeps; infinite: none.
struct KinematicLimits {
  double speed = 0.0;                      // m/s, driving straight
  double turn_rate = 0.0;                  // rad/s, turning in place
  double acceleration = INFINITY;          // m/s², speeding up and slowing down
  double angular_acceleration = INFINITY;  // rad/s²
  // A differential drive's wheels (wheel_base > 0): each wheel's speed is the body's speed,
  // or half the wheel base times the turn rate.
  double wheel_base = 0.0;  // m
};

class Kinematics {
 public:
  virtual ~Kinematics() = default;
  // dt seconds of motion from `from` in `state` toward `to`. A body driving toward another
  // point than `to` (`driving_to`) and too fast to turn stops at once (hard_stop).
  virtual BodyMotion move(Vec2 from, const BodyState& state, Vec2 driving_to, Vec2 to,
                          double dt) const = 0;
  virtual const KinematicLimits& limits() const = 0;
};

// What a kinematics is built for: the robots' top speed (robots.max_speed).
struct KinematicsContext {
  double max_speed = 0.0;
};

struct KinematicsEntry : ComponentInfo {
  // Returns null for the single integrator, whose motion is the controller's own.
  std::function<std::unique_ptr<Kinematics>(const KinematicsContext&, const Params&)> make;
};

// A scenario's "robots": {"kinematics": {"type": NAME, ...}}.
struct KinematicsConfig {
  std::string type = "single_integrator";
  Params params;
};

}  // namespace covsim
