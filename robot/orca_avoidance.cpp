#include "robot/orca_avoidance.hpp"

#include <cmath>

#include "geometry/velocity_program.hpp"

namespace covsim {

namespace {

// The half-plane of the robot's velocities that avoids neighbour n (van den Berg et al.,
// Section 5.1): u is the least change of the relative velocity that leaves the truncated
// velocity obstacle, the robot taking `share` of it.
VelocityConstraint orca_plane(const AvoidanceQuery& q, const SensedNeighbor& n, double horizon,
                              double share) {
  const Vec2 rel_pos = n.position - q.position;
  const Vec2 rel_vel = q.velocity - n.velocity;
  const double dist2 = norm2(rel_pos);
  const double reach = 2.0 * q.radius;
  const double reach2 = reach * reach;
  Vec2 direction, u;
  if (dist2 > reach2) {
    // w: from the centre of the cut-off disk (rel_pos / horizon) to the relative velocity.
    const Vec2 w = rel_vel - rel_pos / horizon;
    const double w2 = norm2(w);
    const double along = dot(w, rel_pos);
    if (along < 0.0 && along * along > reach2 * w2) {
      // Nearest to the cut-off disk.
      const double wn = std::sqrt(w2);
      const Vec2 unit = w / wn;
      direction = {unit.y, -unit.x};
      u = (reach / horizon - wn) * unit;
    } else {
      // Nearest to a leg of the cone.
      const double leg = std::sqrt(dist2 - reach2);
      if (cross(rel_pos, w) > 0.0) {
        direction =
            Vec2{rel_pos.x * leg - rel_pos.y * reach, rel_pos.x * reach + rel_pos.y * leg} / dist2;
      } else {
        direction =
            -Vec2{rel_pos.x * leg + rel_pos.y * reach, -rel_pos.x * reach + rel_pos.y * leg} /
            dist2;
      }
      u = dot(rel_vel, direction) * direction - rel_vel;
    }
  } else {
    // Already touching: leave within one motion step.
    const Vec2 w = rel_vel - rel_pos / q.step_time;
    const double wn = norm(w);
    const Vec2 unit = wn > 0.0 ? w / wn : Vec2{-rel_pos.x, -rel_pos.y} / std::sqrt(dist2);
    direction = {unit.y, -unit.x};
    u = (reach / q.step_time - wn) * unit;
  }
  return VelocityConstraint{q.velocity + share * u, direction};
}

bool standing(const SensedNeighbor& n) {
  return n.velocity == Vec2{};
}

}  // namespace

Vec2 OrcaAvoidance::velocity(const AvoidanceQuery& q) {
  std::vector<VelocityConstraint> planes;
  planes.reserve(q.neighbors.size());
  for (const SensedNeighbor& n : q.neighbors) {
    if (n.position == q.position) continue;  // no direction to avoid it in
    planes.push_back(orca_plane(q, n, horizon_, standing(n) ? 1.0 : 0.5));
  }
  bool free = norm(q.preferred) <= q.max_speed;
  for (const VelocityConstraint& h : planes)
    free = free && cross(h.direction, q.preferred - h.point) >= 0.0;
  if (free) return q.preferred;
  const double c = std::cos(bias_), s = std::sin(bias_);
  const Vec2 turned{c * q.preferred.x + s * q.preferred.y, -s * q.preferred.x + c * q.preferred.y};
  return closest_permitted_velocity(planes, q.max_speed, turned).velocity;
}

double OrcaAvoidance::range(double radius, double max_speed, double) const {
  // Two bodies closing at twice the top speed meet within the horizon only from nearer.
  return range_ > 0.0 ? range_ : 2.0 * radius + 2.0 * max_speed * horizon_;
}

AvoidanceEntry orca_avoidance_entry() {
  AvoidanceEntry e;
  e.name = "orca";
  e.description =
      "optimal reciprocal collision avoidance: velocities that keep bodies apart for a time "
      "horizon, from sensed neighbours";
  e.params = {
      ParamSpec::number("time_horizon", "s",
                        "how far ahead bodies are kept apart if every robot holds its velocity")
          .positive()
          .defaults_to(2.0),
      ParamSpec::number("range", "m",
                        "how far a robot senses its neighbours (null: as far as one can matter "
                        "within the horizon, 2 radius + 2 max_speed time_horizon)")
          .positive()
          .or_null()
          .defaults_to(std::monostate{}),
      ParamSpec::number("bias", "rad",
                        "the preferred velocity turned right by this when anything constrains "
                        "it, so that robots meeting head on pass on their right")
          .at_least(0.0)
          .at_most(1.0)
          .defaults_to(0.1)};
  e.make = [](const Params& p) {
    return std::make_unique<OrcaAvoidance>(p.number("time_horizon"),
                                           p.maybe_number("range").value_or(0.0), p.number("bias"));
  };
  return e;
}

}  // namespace covsim
