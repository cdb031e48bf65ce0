#include "robot/turn_then_drive.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace covsim {

Travel travel(double length, double v0, double top_speed, double acceleration, double time) {
  Travel t;
  if (length <= 0.0) {
    t.done = true;
    return t;
  }
  if (std::isinf(acceleration)) {
    t.covered = std::min(length, top_speed * time);
    t.done = t.covered == length;
    t.time = t.done ? length / top_speed : time;
    t.speed = t.done ? 0.0 : top_speed;
    return t;
  }
  const double a = acceleration;
  v0 = std::min(v0, top_speed);
  // Up to the peak speed, cruise, down to rest at the end: the peak is the top speed or where
  // speeding up from v0 and slowing down to rest meet.
  const double peak = std::min(top_speed, std::sqrt(a * length + 0.5 * v0 * v0));
  const double t1 = std::max(0.0, peak - v0) / a, d1 = (peak * peak - v0 * v0) / (2 * a);
  const double t3 = peak / a, d3 = peak * peak / (2 * a);
  const double d2 = std::max(0.0, length - d1 - d3), t2 = peak > 0.0 ? d2 / peak : 0.0;
  const double total = t1 + t2 + t3;
  if (time >= total) {
    t.covered = length;
    t.time = total;
    t.done = true;
    return t;
  }
  t.time = time;
  if (time <= t1) {
    t.covered = v0 * time + 0.5 * a * time * time;
    t.speed = v0 + a * time;
  } else if (time <= t1 + t2) {
    t.covered = d1 + peak * (time - t1);
    t.speed = peak;
  } else {
    const double tau = time - t1 - t2;
    t.covered = d1 + d2 + peak * tau - 0.5 * a * tau * tau;
    t.speed = std::max(0.0, peak - a * tau);
  }
  t.covered = std::min(t.covered, length);
  return t;
}

namespace {
// The angle from a to b, in (-π, π].
double turn_between(double a, double b) {
  double d = std::remainder(b - a, 2 * std::numbers::pi);
  if (d <= -std::numbers::pi) d += 2 * std::numbers::pi;
  return d;
}
}  // namespace

BodyMotion TurnThenDrive::move(Vec2 from, const BodyState& state, Vec2 driving_to, Vec2 to,
                               double dt) const {
  BodyMotion m;
  m.position = from;
  m.state = state;
  const double length = distance(from, to);
  if (length == 0.0) {
    m.state.speed = m.state.turn_rate = 0.0;
    m.arrived = true;
    return m;
  }
  const double bearing = std::atan2(to.y - from.y, to.x - from.x);
  double turn = turn_between(state.heading, bearing);
  double speed = state.speed;
  if (speed > 0.0) {
    // Driving toward another point: it goes on only if the new one lies straight ahead and
    // it can still stop there; otherwise it stops at once.
    const double braking =
        std::isinf(limits_.acceleration) ? 0.0 : speed * speed / (2 * limits_.acceleration);
    if (!(driving_to == to) && (turn != 0.0 || braking > length)) {
      m.hard_stop = !std::isinf(limits_.acceleration);
      speed = 0.0;
    }
  }
  double left = dt;
  if (speed == 0.0 && turn != 0.0) {
    // Turning in place; a turn the other way than the body was turning starts from rest.
    const double sign = turn > 0.0 ? 1.0 : -1.0;
    const double rate = state.turn_rate * sign > 0.0 ? std::fabs(state.turn_rate) : 0.0;
    const Travel t =
        travel(std::fabs(turn), rate, limits_.turn_rate, limits_.angular_acceleration, left);
    m.turning = t.time;
    if (!t.done) {
      m.state.heading = state.heading + sign * t.covered;
      m.state.turn_rate = sign * t.speed;
      m.state.speed = 0.0;
      return m;
    }
    left -= t.time;
    turn = 0.0;
  }
  m.state.heading = bearing;
  m.state.turn_rate = 0.0;
  const Travel t = travel(length, speed, limits_.speed, limits_.acceleration, left);
  m.arrived = t.done;
  m.position = t.done ? to : from + (t.covered / length) * (to - from);
  m.state.speed = t.speed;
  return m;
}

}  // namespace covsim
