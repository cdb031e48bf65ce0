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
double line_distance(Vec2 p, const ContactEdge& c) {
  const double len = distance(c.a, c.b);
  return len > 0.0 ? std::fabs(cross(c.b - c.a, p - c.a)) / len : distance(p, c.a);
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
      return FreeRay{0.0, x};
  }
  if (in && out) {
    const bool convex = cross(x - in->a, out->b - x) > 0.0;
    const bool free = convex ? (left(*in) && left(*out)) : (left(*in) || left(*out));
    if (!free) return FreeRay{0.0, x};
  } else if (in || out) {
    if (!left(in ? *in : *out)) return FreeRay{0.0, x};
  }
  // A sensed piece through the robot that lies along a touched wall is that wall, judged
  // above: it blocks only beyond the tolerance. Any other blocks however near.
  const auto touched = [&](const SensedPiece& p) {
    if (distance(project_to_segment(x, p.a, p.b).point, x) > tolerance) return false;
    return std::any_of(r.contacts.begin(), r.contacts.end(), [&](const ContactEdge& c) {
      return line_distance(p.a, c) <= tolerance && line_distance(p.b, c) <= tolerance;
    });
  };
  FreeRay f{kInf, std::nullopt};
  for (const SensedPiece& piece : r.visible().pieces) {
    const Vec2 a = piece.a, s = piece.b - a;
    const double denom = cross(u, s);
    // Parallel: running along it. |s.x| + |s.y| bounds norm(s), so twice that decides the
    // test without the hypot for all but nearly parallel pieces.
    const double magnitude = std::fabs(denom);
    if (magnitude <= 2e-12 * (std::fabs(s.x) + std::fabs(s.y)) && magnitude <= 1e-12 * norm(s))
      continue;
    const double t = cross(a - x, s) / denom;
    const double v = cross(a - x, u) / denom;
    if (t < f.distance && v >= -1e-12 && v <= 1.0 + 1e-12 &&
        t > (touched(piece) ? tolerance : 0.0)) {
      f.distance = t;
      f.blocked_at = x + t * u;
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

std::vector<SensedChain> sensed_chains(const SensorReading& r, double tolerance) {
  const std::vector<SensedPiece>& pieces = r.visible().pieces;
  const std::size_t n = pieces.size();
  std::vector<SensedChain> chains;
  if (n == 0) return chains;
  const auto joined = [&](std::size_t k) {  // piece k runs on into piece k + 1
    return within(pieces[k].b, pieces[(k + 1) % n].a, tolerance);
  };
  // Chains start after a jump; with none, the whole boundary is one closed chain.
  std::size_t first = n;
  for (std::size_t k = 0; k < n && first == n; ++k) {
    if (!joined((k + n - 1) % n)) first = k;
  }
  const bool closed = first == n;
  if (closed) first = 0;
  for (std::size_t done = 0; done < n;) {
    SensedChain c;
    c.first_piece = (first + done) % n;
    c.closed = closed;
    c.points.push_back(pieces[c.first_piece].a);
    do {
      const SensedPiece& p = pieces[(first + done) % n];
      if (beyond(p.b, c.points.back(), tolerance)) c.points.push_back(p.b);
      ++c.piece_count;
      ++done;
    } while (done < n && joined((first + done + n - 1) % n));
    chains.push_back(std::move(c));
  }
  return chains;
}

PolylinePlace closest_place(const std::vector<Vec2>& points, Vec2 p) {
  PolylinePlace best{0, points.empty() ? p : points.front(), kInf};
  if (points.size() == 1) best.distance = distance(p, points.front());
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Vec2 q = project_to_segment(p, points[k], points[k + 1]).point;
    const double d = distance(q, p);
    if (d < best.distance) best = {k, q, d};
  }
  return best;
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
  for (Vec2 o : r.visible().discontinuities) {
    const double dx = distance(o, x), dgo = distance(o, goal);
    if (dx > tolerance && dgo < bound) nodes.push_back(TangentNode{o, dx + dgo, false});
  }
  return nodes;
}

ReachPoint reach_point(const SensorReading& r, Vec2 goal, const SensedChain* followed,
                       double tolerance, const std::function<bool(Vec2)>& admissible) {
  ReachPoint best{r.position, kInf};
  const auto consider = [&](Vec2 p) {
    const double d = distance(p, goal);
    if (d < best.distance && (!admissible || admissible(p))) best = {p, d};
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
  const std::vector<Vec2>& o = r.visible().discontinuities;
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
  const std::size_t n = r.visible().pieces.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (followed != nullptr && followed->holds_piece(k, n)) continue;
    consider(project_to_segment(goal, r.visible().pieces[k].a, r.visible().pieces[k].b).point);
  }
  return best;
}

}  // namespace covsim
