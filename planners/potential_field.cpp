#include "planners/potential_field.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/predicates.hpp"
#include "planners/planner_map.hpp"

namespace covsim {

PotentialFieldParams PotentialFieldParams::for_environment(double diameter) {
  PotentialFieldParams p;
  p.influence = 0.1 * diameter;
  p.progress = 1e-3 * diameter;
  return p;
}

namespace {
// The walls a reading shows: its visible pieces and the walls it touches.
template <class F>
void for_each_sensed_wall(const SensorReading& r, F&& f) {
  for (const SensedPiece& p : r.visible().pieces)
    f(p.a, p.b);
  for (const ContactEdge& c : r.contacts)
    f(c.a, c.b);
}

// Whether x -> y meets no wall the reading shows, but for one it starts or ends on, which it
// must leave into (or reach from) that wall's free side, its left.
bool open_in_reading(const SensorReading& r, Vec2 x, Vec2 y, double tolerance) {
  bool open = true;
  const auto on = [&](Vec2 p, Vec2 a, Vec2 b) {
    return distance(p, project_to_segment(p, a, b).point) <= tolerance;
  };
  for_each_sensed_wall(r, [&](Vec2 a, Vec2 b) {
    if (on(x, a, b)) {
      open = open && cross(b - a, y - x) >= 0.0;
    } else if (on(y, a, b)) {
      open = open && cross(b - a, x - y) >= 0.0;
    } else if (segments_intersect(x, y, a, b)) {
      open = false;
    }
  });
  return open;
}

// x -> y, stopped where it first crosses a wall the reading shows.
Vec2 advance_in_reading(const SensorReading& r, Vec2 x, Vec2 y) {
  double first = 1.0;
  const Vec2 d = y - x;
  for_each_sensed_wall(r, [&](Vec2 a, Vec2 b) {
    if (!(orientation(x, y, a) * orientation(x, y, b) < 0 &&
          orientation(a, b, x) * orientation(a, b, y) < 0))
      return;
    const double t = cross(a - x, b - a) / cross(d, b - a);
    first = std::min(first, std::max(0.0, t));
  });
  return first < 1.0 ? x + first * d : y;
}
}  // namespace

void PotentialField::set_goal(Vec2 goal) {
  goal_ = goal;
  status_ = PlanStatus::moving;
  best_ = INFINITY;
  since_best_ = 0;
}

Vec2 PotentialField::force(const SensorReading& r) const {
  const Vec2 x = r.position;
  const double dg = distance(x, goal_);
  Vec2 f = dg > 0.0 ? (goal_ - x) / dg : Vec2{0, 0};
  const double d0 = p_.influence;
  // Near the goal the push fades with (dg / d0)² (Ge and Cui, 2000), so a goal close to a
  // wall is not hidden behind that wall's own repulsion.
  const double fade = std::min(1.0, (dg / d0) * (dg / d0));
  const double eta = fade * p_.repulsive_gain * d0 * d0 * d0 / 48.0;
  for (const SensedPiece& piece : r.visible().pieces) {
    const Vec2 o = project_to_segment(x, piece.a, piece.b).point;
    const double d = distance(x, o);
    if (d >= d0 || d <= env_.tolerance()) continue;  // touching walls are handled by sliding
    f = f + (eta * (1.0 / d - 1.0 / d0) / (d * d * d)) * (x - o);
  }
  // Slide along touched walls: drop the part of the motion into the obstacle (free space is
  // on the left of each contact edge).
  for (const ContactEdge& c : r.contacts) {
    const Vec2 e = c.b - c.a;
    const double len = norm(e);
    if (len == 0.0) continue;
    const Vec2 inward = perp(e) / len;  // into free space
    const double into = dot(f, inward);
    if (into < 0.0) f = f - into * inward;
  }
  return f;
}

PlanStep PotentialField::step(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (status_ != PlanStatus::moving) return PlanStep{x, status_};
  const double dg = distance(x, goal_);
  if (dg <= env_.tolerance()) {
    status_ = PlanStatus::reached;
    return PlanStep{goal_, status_};
  }
  if (dg < best_ - p_.progress) {
    best_ = dg;
    since_best_ = 0;
  } else if (++since_best_ >= p_.stall_window) {
    status_ = PlanStatus::stalled;
    return PlanStep{x, status_};
  }
  // Final approach: a goal near enough and in sight is driven to straight.
  if (dg <= std::max(p_.influence, max_step) && (dg <= r.range || dg <= max_step) &&
      (p_.sensed ? open_in_reading(r, x, goal_, env_.tolerance())
                 : env_.segment_inside(x, goal_))) {
    if (dg <= max_step) {
      // On what it senses, a last step it could not see is claimed once taken, and so is
      // one it saw through noisy ranges (a goal within the noise of a wall may lie beyond it).
      if (!p_.sensed || (dg <= r.range && !p_.noisy)) status_ = PlanStatus::reached;
      return PlanStep{goal_, status_};
    }
    return PlanStep{x + (max_step / dg) * (goal_ - x), status_};
  }
  const Vec2 f = force(r);
  const double fn = norm(f);
  if (fn <= 1e-12) return PlanStep{x, status_};  // a minimum: the window will tell
  const Vec2 to = x + (std::min(max_step, dg) / fn) * f;
  return PlanStep{p_.sensed ? advance_in_reading(r, x, to) : env_.advance(x, to), status_};
}

PlannerEntry potential_field_entry() {
  PlannerEntry e;
  e.name = "potential_field";
  e.reads_range = true;
  e.description = "Khatib's attractive and repulsive potentials over what the range sensor sees";
  e.params = {
      ParamSpec::number("influence", "m", "distance d0 within which walls repel")
          .greater_than(0)
          .derived("1/10 of the diameter of Ω's bounding box",
                   [](const Environment& env) {
                     return PotentialFieldParams::for_environment(env.diameter()).influence;
                   }),
      ParamSpec::number("repulsive_gain", "", "η in units of d0³/48").at_least(0).defaults_to(1.0),
      ParamSpec::integer("stall_window", "steps",
                         "steps without progress after which it reports a stall")
          .at_least(1)
          .at_most(1e6)
          .defaults_to(std::uint64_t{50}),
      planner_map_param()};
  e.make = [](const PlannerContext& ctx, const Params& params) -> PlannerSource {
    PotentialFieldParams p = PotentialFieldParams::for_environment(ctx.environment.diameter());
    if (auto v = params.maybe_number("influence")) p.influence = *v;
    p.repulsive_gain = params.number("repulsive_gain");
    p.stall_window = static_cast<std::size_t>(params.integer("stall_window"));
    p.sensed = plans_on_sensed_map(params);
    p.progress = std::max(p.progress, 3.0 * ctx.sensor.spread());
    p.noisy = ctx.sensor.spread() > 0.0;
    const Environment* env = &ctx.environment;
    return [env, p] { return std::make_unique<PotentialField>(*env, p); };
  };
  return e;
}

}  // namespace covsim
