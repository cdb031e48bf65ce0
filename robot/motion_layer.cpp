#include "robot/motion_layer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "net/receiver_grid.hpp"
#include "robot/collision_avoidance_registry.hpp"
#include "robot/guarded_call.hpp"
#include "robot/kinematics_registry.hpp"
#include "robot/turn_then_drive.hpp"

namespace covsim {

MotionLayer::MotionLayer(const Kernel& kernel, const Environment& env, const CoverageConfig& config,
                         std::vector<Robot>& robots, MotionHost host)
    : kernel_(kernel), env_(env), config_(config), robots_(robots), host_(std::move(host)) {
  if (config_.radius > 0.0 && config_.avoidance.type != AvoidanceConfig{}.type)
    avoidance_ = make_collision_avoidance(config_.avoidance);
  kinematics_ = make_kinematics(config_.kinematics, KinematicsContext{config_.max_speed});
  if (avoidance_) {
    // The robots near one, for sensing and for the clearance of a motion, without testing
    // every robot.
    const double step = config_.max_speed * config_.loop2_period.seconds();
    near_range_ = std::max(
        avoidance_->range(config_.radius, config_.max_speed, config_.loop2_period.seconds()),
        2.0 * config_.radius + step);
    std::vector<Vec2> at;
    for (const Robot& r : robots_)
      at.push_back(r.position);
    near_ = std::make_unique<ReceiverGrid>(near_range_, at);
  }
}

MotionLayer::~MotionLayer() = default;

void MotionLayer::moved(const Robot& r, Vec2 p) {
  if (near_) near_->moved(r.id, p);
}

template <class F>
void MotionLayer::for_each_near(Vec2 p, double radius, F&& f) const {
  // In increasing index either way: the same order as a loop over every robot.
  if (!near_ || radius > near_range_) {
    for (const Robot& o : robots_)
      f(o);
    return;
  }
  near_->candidates(p, near_ids_);
  for (const std::uint32_t j : near_ids_)
    f(robots_[j]);
}

void MotionLayer::sense_neighbors(const Robot& r) {
  // Those within the avoidance's range and in sight.
  const double range =
      avoidance_->range(config_.radius, config_.max_speed, config_.loop2_period.seconds());
  neighbors_.clear();
  for_each_near(r.position, range, [&](const Robot& o) {
    if (o.id == r.id || !within(o.position, r.position, range) ||
        !env_.segment_inside(r.position, o.position))
      return;
    neighbors_.push_back(SensedNeighbor{o.position, o.velocity});
  });
}

bool MotionLayer::arrive_at_waypoint(Robot& r) {
  const PlanStatus status = r.waypoint->status;
  r.waypoint.reset();
  if (r.deadlocked) ++deadlocks_resolved_;
  r.deadlocked = false;
  return host_.arrive(r, status);
}

Vec2 MotionLayer::drive(Robot& r, Vec2 to) {
  if (!kinematics_) return to;
  const BodyMotion m =
      kinematics_->move(r.position, r.body, r.driving_to, to, config_.loop2_period.seconds());
  r.body = m.state;
  r.driving_to = to;
  if (m.hard_stop) ++hard_stops_;
  turn_time_ += m.turning;
  return m.arrived ? to : m.position;
}

Vec2 MotionLayer::avoiding_velocity(const Robot& r, Vec2 preferred, double max_speed) {
  sense_neighbors(r);
  return guarded_call(r.id, "collision avoidance", config_.avoidance.type, kernel_.now(), [&] {
    const Vec2 v =
        avoidance_->velocity(AvoidanceQuery{r.position, r.velocity, preferred, config_.radius,
                                            max_speed, config_.loop2_period.seconds(), neighbors_});
    if (!is_finite(v) || !(norm(v) <= max_speed * (1 + 1e-9)))
      throw std::invalid_argument(fmt::format(
          "a velocity must be finite and at most {} m/s, found ({}, {})", max_speed, v.x, v.y));
    return v;
  });
}

bool MotionLayer::follow_waypoint(Robot& r) {
  const PlanStep w = *r.waypoint;
  const double dt = config_.loop2_period.seconds();
  const Environment& space = host_.free_space(r.id);
  // A step that ends the planner's episode (at the goal, or settled at the closest point)
  // is followed to its point; a step on the way only as far along its direction, so that a
  // detour round a neighbour is kept rather than undone.
  const bool last = w.status != PlanStatus::moving;
  const Vec2 planned_way = w.next - r.waypoint_from;
  const double planned_length = norm(planned_way);
  const auto left = [&](Vec2 p) {
    return last || planned_length == 0.0 ? distance(p, w.next)
                                         : dot(w.next - p, planned_way) / planned_length;
  };
  const Vec2 preferred =
      last || planned_length == 0.0 || r.position == r.waypoint_from
          ? (w.next - r.position) / dt
          : (std::max(0.0, left(r.position)) / planned_length / dt) * planned_way;
  Vec2 to = w.next;
  bool blocked = false;
  if (avoidance_) {
    // No faster than the waypoint needs: a detour never passes it.
    const Vec2 v = avoiding_velocity(r, preferred, norm(preferred));
    to = v == preferred ? w.next : r.position + dt * v;
    // A detour keeps the waypoint in sight, within the free space; otherwise only the part of
    // the velocity along the way to it is taken.
    if (!(to == w.next) &&
        !(space.segment_inside(r.position, to) && space.segment_inside(to, w.next))) {
      const Vec2 d = w.next - r.position;
      const double f = std::clamp(dot(to - r.position, d) / norm2(d), 0.0, 1.0);
      to = f == 1.0 ? w.next : r.position + f * d;
    }
    // Never nearer to a body than touching, whatever the avoidance chose.
    const double g = clear_fraction(r, to);
    if (g < 1.0) to = r.position + g * (to - r.position);
    // Blocked: a tenth of the way or less made good (pushed back counts as blocked).
    const double before = left(r.position);
    blocked = before - left(to) < 0.1 * before;
  }
  // The body carries the motion out as far as it can in the step; the way to `to` is clear
  // and free, and the body stays on it.
  const Vec2 at = drive(r, to);
  host_.move_to(r, at);
  if (!avoidance_) return at == w.next ? arrive_at_waypoint(r) : true;
  // A deadlock begins after kDeadlockTime blocked, and lasts until the robot reaches a
  // planner step again.
  r.blocked_time = blocked ? r.blocked_time + dt : 0.0;
  if (r.deadlocked) {
    deadlock_time_ += dt;
  } else if (r.blocked_time >= kDeadlockTime) {
    r.deadlocked = true;
    ++deadlocks_;
    deadlock_time_ += r.blocked_time;
  }
  // On the way, nine tenths of the step along its direction will do (for a body at rest, or
  // one that can change direction at once): the planner steps on from where the robot is.
  if (at == w.next ||
      (!last && (!kinematics_ || r.body.speed == 0.0) && left(at) <= 0.1 * planned_length)) {
    r.displaced = !(at == w.next);
    return arrive_at_waypoint(r);
  }
  if (blocked && std::fmod(r.blocked_time + 0.5 * dt, kDeadlockTime) < dt) resolve(r);
  return true;
}

void MotionLayer::resolve(Robot& r) {
  // Who stands on the waypoint, if anyone.
  Robot* occupant = nullptr;
  for (Robot& o : robots_) {
    if (o.id != r.id && distance(o.position, r.waypoint->next) < 2.0 * config_.radius &&
        (occupant == nullptr ||
         distance(o.position, r.waypoint->next) < distance(occupant->position, r.waypoint->next)))
      occupant = &o;
  }
  if (occupant == nullptr) {
    // Held up by its neighbours' avoidance: the planner is asked again from here.
    r.waypoint.reset();
    r.displaced = true;
  } else if (occupant->deadlocked && occupant->id < r.id) {
    // Two robots in each other's way: the larger id gives way, or, if it has no room to (in
    // a dead end, hemmed in by others), the other one.
    if (!start_giving_way(r, occupant->position) && occupant->give_way == 0.0)
      start_giving_way(*occupant, r.position);
  } else if (!occupant->deadlocked && occupant->give_way == 0.0 && is_settled(occupant->status)) {
    // A robot settled on the way steps aside, then returns to its goal.
    start_giving_way(*occupant, r.position);
  }
}

bool MotionLayer::start_giving_way(Robot& r, Vec2 from) {
  // Two body diameters to its own right as it faces the robot it makes room for (the side
  // ORCA's bias passes on), else back and right, straight back, back and left, or left: the
  // first where the walls and the other bodies leave it a body's radius of way, else the
  // roomiest.
  const Environment& space = host_.free_space(r.id);
  const Vec2 away = r.position - from;
  const Vec2 unit = away / norm(away);
  const double length = 4.0 * config_.radius;
  double room = 0.0;
  r.give_way_to = r.position;
  for (const double turn : {std::numbers::pi / 2, std::numbers::pi / 4, 0.0, -std::numbers::pi / 4,
                            -std::numbers::pi / 2}) {
    const double c = std::cos(turn), s = std::sin(turn);
    const Vec2 d{c * unit.x - s * unit.y, s * unit.x + c * unit.y};
    const Vec2 q = space.advance(r.position, r.position + length * d);
    const double way = clear_fraction(r, q) * distance(r.position, q);
    if (way > room) {
      room = way;
      r.give_way_to = q;
    }
    if (way >= config_.radius) break;
  }
  if (room < 0.5 * config_.radius) {
    r.give_way_to = r.position;
    return false;  // no room to give way
  }
  // As long as it takes to get there (for a body with a heading, to turn round first), twice
  // over: a neighbour in the way may hold it up.
  double time = length / config_.max_speed;
  if (kinematics_) {
    const KinematicLimits& l = kinematics_->limits();
    time = travel(std::numbers::pi, 0.0, l.turn_rate, l.angular_acceleration, INFINITY).time +
           travel(length, 0.0, l.speed, l.acceleration, INFINITY).time;
  }
  r.give_way = std::max(2.0 * time, config_.loop2_period.seconds());
  r.status = PlanStatus::moving;
  r.stable = false;
  ++give_ways_;
  return true;
}

void MotionLayer::give_way(Robot& r) {
  const double dt = config_.loop2_period.seconds();
  const Vec2 to = r.give_way_to;
  const double g = clear_fraction(r, to);
  const Vec2 at = drive(r, g < 1.0 ? r.position + g * (to - r.position) : to);
  host_.move_to(r, at);
  r.give_way = at == to ? 0.0 : std::max(0.0, r.give_way - dt);
  if (r.deadlocked) deadlock_time_ += dt;
  if (r.give_way == 0.0) {
    // Back to its goal, with its planner started afresh from here.
    r.waypoint.reset();
    r.blocked_time = 0.0;
    host_.restart(r);
  }
}

double MotionLayer::clear_fraction(const Robot& r, Vec2 to) const {
  const Vec2 d = to - r.position;
  const double a = norm2(d);
  if (a == 0.0) return 1.0;
  const double reach = 2.0 * config_.radius;
  double g = 1.0;
  for_each_near(r.position, reach + std::sqrt(a), [&](const Robot& o) {
    if (o.id == r.id || !within(o.position, r.position, reach + std::sqrt(a))) return;
    // The first point of the motion nearer to o than touching (or than it already is).
    const Vec2 e = r.position - o.position;
    const double b = 2.0 * dot(e, d);
    if (b >= 0.0) return;  // moving away from o
    const double least = std::min(reach, norm(e));
    const double c = norm2(e) - least * least;
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return;
    const double s = (-b - std::sqrt(disc)) / (2.0 * a);
    g = std::min(g, std::max(0.0, s));
  });
  return g;
}

}  // namespace covsim
