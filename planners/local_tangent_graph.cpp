#include "planners/local_tangent_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace covsim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
Vec2 unit(Vec2 v) {
  const double n = norm(v);
  return n > 0.0 ? v / n : Vec2{0, 0};
}
}  // namespace

FreeRay free_ray(const SensorReading& r, Vec2 u, double tolerance) {
  const Vec2 x = r.position;
  // A wall the robot touches may face the direction: free space is on the left of each edge;
  // at a vertex, on the left of both edges (convex corner) or of either (reflex corner).
  const auto left = [&](const ContactEdge& e) { return cross(unit(e.b - e.a), u) >= -1e-12; };
  const ContactEdge* in = nullptr;
  const ContactEdge* out = nullptr;
  for (const ContactEdge& c : r.contacts) {
    if (within(c.b, x, tolerance))
      in = &c;
    else if (within(c.a, x, tolerance))
      out = &c;
    else if (!left(c))
      return FreeRay{0.0, c.ring};
  }
  if (in && out) {
    const bool convex = cross(x - in->a, out->b - x) > 0.0;
    const bool free = convex ? (left(*in) && left(*out)) : (left(*in) || left(*out));
    if (!free) return FreeRay{0.0, in->ring};
  } else if (in || out) {
    const ContactEdge& c = in ? *in : *out;
    if (!left(c)) return FreeRay{0.0, c.ring};
  }
  FreeRay f{kInf, std::nullopt};
  for (std::size_t k = 0; k < r.visible.pieces.size(); ++k) {
    const Vec2 a = r.visible.pieces[k].a, s = r.visible.pieces[k].b - a;
    const double denom = cross(u, s);
    // Parallel: running along it. |s.x| + |s.y| bounds norm(s), so twice that decides the
    // test without the hypot for all but nearly parallel pieces.
    const double magnitude = std::fabs(denom);
    if (magnitude <= 2e-12 * (std::fabs(s.x) + std::fabs(s.y)) && magnitude <= 1e-12 * norm(s))
      continue;
    const double t = cross(a - x, s) / denom;
    const double v = cross(a - x, u) / denom;
    // A wall met within the tolerance is one the robot touches (judged above) unless it is
    // not among the contacts: then it blocks however near.
    const std::uint32_t edge = r.visible.pieces[k].edge;
    const bool touching = std::any_of(r.contacts.begin(), r.contacts.end(),
                                      [&](const ContactEdge& c) { return c.edge == edge; });
    if (t > (touching ? tolerance : 0.0) && v >= -1e-12 && v <= 1.0 + 1e-12 && t < f.distance) {
      f.distance = t;
      f.blocker = r.piece_rings[k];
    }
  }
  return f;
}

std::optional<ContactEdge> walking_edge(const SensorReading& r, int dir, double tolerance) {
  for (const ContactEdge& c : r.contacts) {
    if (distance(dir > 0 ? c.b : c.a, r.position) > tolerance) return c;
  }
  return std::nullopt;
}

std::vector<TangentNode> tangent_nodes(const SensorReading& r, Vec2 goal, double bound,
                                       double tolerance) {
  std::vector<TangentNode> nodes;
  const Vec2 x = r.position;
  const double dg = distance(goal, x);
  if (dg > 0.0) {
    const FreeRay f = free_ray(r, (goal - x) / dg, tolerance);
    // Free when nothing sensed blocks the way within the range (a contact sensor's range is
    // 0: free unless a wall it touches faces the goal).
    if (f.distance > 0.0 && f.distance >= std::min(r.range, dg) - tolerance)
      nodes.push_back(TangentNode{goal, dg, true});
  }
  for (std::size_t k = 0; k < r.visible.discontinuities.size(); ++k) {
    const Vec2 o = r.visible.discontinuities[k];
    const double dx = distance(o, x), dgo = distance(o, goal);
    if (dx > tolerance && dgo < bound)
      nodes.push_back(TangentNode{o, dx + dgo, false, r.discontinuity_rings[k]});
  }
  return nodes;
}

ReachPoint reach_point(const SensorReading& r, Vec2 goal, std::uint32_t followed,
                       double tolerance) {
  ReachPoint best{r.position, kInf};
  const auto consider = [&](Vec2 p) {
    const double d = distance(p, goal);
    if (d < best.distance) best = {p, d};
  };
  const Vec2 x = r.position;
  const double dg = distance(goal, x);
  if (dg <= tolerance) {
    consider(goal);
    return best;
  }
  const Vec2 u = (goal - x) / dg;
  const FreeRay f = free_ray(r, u, tolerance);
  if (f.distance > 0.0) {
    const double t = std::min({f.distance, dg, r.range});
    consider(t == dg ? goal : x + t * u);
  }
  const std::vector<Vec2>& o = r.visible.discontinuities;
  for (Vec2 p : o)
    consider(p);
  // Discontinuities come in pairs (a piece's end, the next piece's start); a pair on one ray
  // from the robot (an occluding vertex and the wall behind it) bounds a shadow segment.
  // Pairs at different angles face a free arc at the range's edge instead: not a segment.
  for (std::size_t k = 0; k + 1 < o.size(); k += 2) {
    const Vec2 a = unit(o[k] - x), b = unit(o[k + 1] - x);
    if (std::fabs(cross(a, b)) <= 1e-9 && dot(a, b) > 0.0)
      consider(project_to_segment(goal, o[k], o[k + 1]).point);
  }
  for (std::size_t k = 0; k < r.visible.pieces.size(); ++k) {
    if (r.piece_rings[k] == followed) continue;
    consider(project_to_segment(goal, r.visible.pieces[k].a, r.visible.pieces[k].b).point);
  }
  return best;
}

}  // namespace covsim
