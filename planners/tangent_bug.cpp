#include "planners/tangent_bug.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/ring_validation.hpp"

namespace covsim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
Vec2 unit(Vec2 v) {
  const double n = norm(v);
  return n > 0.0 ? v / n : Vec2{0, 0};
}
}  // namespace

std::string_view to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::moving:
      return "moving";
    case PlanStatus::reached:
      return "reached";
    case PlanStatus::projected:
      return "projected";
    case PlanStatus::stalled:
      return "stalled";
  }
  return "unknown";
}

TangentBugParams TangentBugParams::for_environment(double diameter, double boundary_length) {
  return TangentBugParams{1e-6 * diameter, 1e-9 * diameter, 4.0 * boundary_length + diameter};
}

void TangentBug::set_goal(Vec2 goal) {
  goal_ = goal;
  has_goal_ = true;
  mode_ = Mode::to_goal;
  status_ = PlanStatus::moving;
  path_ = 0.0;
  h_prev_ = kInf;
  heading_.reset();
  idle_steps_ = 0;
  followed_min_.clear();
}

PlanStep TangentBug::move(const SensorReading& r, Vec2 next, PlanStatus s) {
  const double d = distance(r.position, next);
  path_ += d;
  idle_steps_ = d > p_.tolerance ? 0 : idle_steps_ + 1;
  return PlanStep{next, s};
}

PlanStep TangentBug::finish(Vec2 at, PlanStatus s) {
  mode_ = Mode::done;
  status_ = s;
  return PlanStep{at, s};
}

PlanStep TangentBug::step(const SensorReading& r, double max_step) {
  if (!has_goal_ || mode_ == Mode::done) return PlanStep{r.position, status_};
  if (path_ > p_.path_budget) return finish(r.position, PlanStatus::stalled);
  // Proposing to stay put, step after step, while meant to be moving: give up.
  if (idle_steps_ > kMaxIdleSteps) return finish(r.position, PlanStatus::stalled);
  for (const ContactEdge& c : r.contacts)
    remember(c);
  switch (mode_) {
    case Mode::to_goal:
      return motion_to_goal(r, max_step);
    case Mode::to_boundary:
      if (!r.contacts.empty())
        return begin_following(r, max_step, Free{0.0, r.contacts.front().ring, std::nullopt});
      // Toward the obstacle until touching it: the sensed point may be off by noise.
      return move(r, r.position + max_step * boundary_direction_);
    case Mode::follow:
      return follow(r, max_step);
    case Mode::to_projection:
      return to_projection(r, max_step);
    case Mode::done:
      break;
  }
  return PlanStep{r.position, status_};
}

PlanStep TangentBug::motion_to_goal(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  const double d = distance(goal_, x);
  if (d <= p_.tolerance) {
    path_ += d;
    return finish(goal_, PlanStatus::reached);
  }
  // Touching an obstacle already circled that holds the goal: project at once.
  for (const ContactEdge& c : r.contacts) {
    if (memory_[c.ring].complete() && goal_inside(c.ring))
      return go_to_projection(r, max_step, c.ring);
  }
  const Vec2 u = (goal_ - x) / d;
  const double reach = std::min(d, r.range);
  const Free f = free_distance(r, u, reach);
  // Free when nothing sensed blocks the way within range; a wall the robot is pressed
  // against blocks whatever the range.
  if (f.distance > 0.0 && f.distance >= reach - p_.tolerance) {
    h_prev_ = kInf;
    heading_ = goal_;
    return move(r, x + std::min(max_step, d) * u);
  }
  // Blocked: head for the discontinuity point with the least heuristic distance, while it
  // keeps decreasing.
  std::optional<Vec2> best;
  double h_best = kInf;
  for (Vec2 o : r.visible.discontinuities) {
    const double dx = distance(o, x);
    if (dx <= p_.tolerance) continue;
    const double h = dx + distance(o, goal_);
    if (h < h_best) {
      h_best = h;
      best = o;
    }
  }
  if (best && h_best < h_prev_ - p_.progress) {
    h_prev_ = h_best;
    heading_ = best;
    return move(r, x + std::min(max_step, distance(*best, x)) * unit(*best - x));
  }
  return begin_following(r, max_step, f);
}

PlanStep TangentBug::begin_following(const SensorReading& r, double max_step, const Free& blocked) {
  const Vec2 x = r.position;
  if (r.contacts.empty()) {
    // Get onto the blocking obstacle first: the closest point of the piece in the way.
    if (!blocked.piece) return finish(x, PlanStatus::stalled);
    const VisiblePiece& piece = r.visible.pieces[*blocked.piece];
    const Vec2 target = project_to_segment(x, piece.a, piece.b).point;
    boundary_direction_ = unit(target - x);
    if (norm(boundary_direction_) == 0.0) boundary_direction_ = unit(goal_ - x);
    mode_ = Mode::to_boundary;
    ring_ = *blocked.blocker;
    return move(r, x + max_step * boundary_direction_);
  }
  const std::uint32_t ring = r.contacts.front().ring;
  if (memory_[ring].complete() && goal_inside(ring)) return go_to_projection(r, max_step, ring);
  // Follow in the direction that continues toward the point last headed for (toward the
  // goal if that point is where the robot stands).
  const bool heading_ahead = heading_ && distance(*heading_, x) > p_.tolerance;
  const Vec2 ref = unit(heading_ahead ? *heading_ - x : goal_ - x);
  int dir = 1;
  double best_score = -kInf;
  for (int d : {1, -1}) {
    const auto e = walking_edge(r, d);
    if (!e) continue;
    const double score = dot(unit((d > 0 ? e->b : e->a) - x), ref);
    if (score > best_score + 1e-12) {
      best_score = score;
      dir = d;
    }
  }
  const auto e = walking_edge(r, dir);
  if (!e) return finish(x, PlanStatus::stalled);
  mode_ = Mode::follow;
  ring_ = ring;
  dir_ = dir;
  start_ = x;
  start_edge_ = e->edge;
  left_start_ = false;
  followed_min_.try_emplace(ring, distance(goal_, x));
  return follow(r, max_step);
}

PlanStep TangentBug::follow(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  double& d_followed = followed_min_.try_emplace(ring_, kInf).first->second;
  // The followed obstacle as sensed now counts toward d_followed (except the point under
  // the robot, so that a contact sensor can still leave where it stands).
  double d_reach = kInf;
  Vec2 leave_to = x;
  for (std::size_t k = 0; k < r.visible.pieces.size(); ++k) {
    const Vec2 q = project_to_segment(goal_, r.visible.pieces[k].a, r.visible.pieces[k].b).point;
    const double dq = distance(q, goal_);
    if (r.piece_rings[k] == ring_) {
      if (distance(q, x) > p_.tolerance) d_followed = std::min(d_followed, dq);
    } else if (dq < d_reach) {
      d_reach = dq;
      leave_to = q;
    }
  }
  for (Vec2 o : r.visible.discontinuities) {
    if (distance(o, goal_) < d_reach) {
      d_reach = distance(o, goal_);
      leave_to = o;
    }
  }
  // The free point straight toward the goal (the robot's own position if it can move that
  // way but senses nothing further).
  const double dg = distance(goal_, x);
  if (dg > p_.tolerance) {
    const Vec2 u = (goal_ - x) / dg;
    const Free f = free_distance(r, u, std::min(dg, r.range));
    if (f.distance > 0.0) {
      const double t = std::min({f.distance, dg, r.range});
      const Vec2 fp = x + t * u;
      if (distance(fp, goal_) < d_reach) {
        d_reach = distance(fp, goal_);
        leave_to = fp;
      }
    }
  }
  if (d_reach < d_followed - p_.progress) {
    mode_ = Mode::to_goal;
    h_prev_ = kInf;
    heading_ = leave_to;
    d_followed = std::min(d_followed, d_reach);  // the next leave must do better
    return move(r, x + std::min(max_step, distance(leave_to, x)) * unit(leave_to - x));
  }
  d_followed = std::min(d_followed, dg);

  const auto e = walking_edge(r, dir_);
  if (!e) return finish(x, PlanStatus::stalled);
  const Vec2 end = dir_ > 0 ? e->b : e->a;
  const Vec2 next = x + std::min(max_step, distance(end, x)) * unit(end - x);
  if (e->edge != start_edge_) left_start_ = true;
  // Back where following began without having left: the goal is unreachable.
  if (left_start_ && distance(project_to_segment(start_, x, next).point, start_) <= p_.tolerance) {
    memory_[ring_].size = static_cast<std::uint32_t>(memory_[ring_].edges.size());
    return go_to_projection(r, max_step, ring_);
  }
  return move(r, next);
}

PlanStep TangentBug::go_to_projection(const SensorReading& r, double max_step, std::uint32_t ring) {
  const Vec2 x = r.position;
  const auto [q, j] = closest_on_ring(ring);
  ring_ = ring;
  projection_ = q;
  projection_edge_ = j;
  mode_ = Mode::to_projection;
  if (distance(q, x) <= p_.tolerance) {
    path_ += distance(q, x);
    return finish(q, PlanStatus::projected);
  }
  // The shorter way round.
  const auto ef = walking_edge(r, 1), eb = walking_edge(r, -1);
  const double af = ef ? arc(ring, x, ef->index, q, j, 1) : kInf;
  const double ab = eb ? arc(ring, x, eb->index, q, j, -1) : kInf;
  dir_ = af <= ab ? 1 : -1;
  return to_projection(r, max_step);
}

PlanStep TangentBug::to_projection(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (distance(projection_, x) <= p_.tolerance) {
    path_ += distance(projection_, x);
    return finish(projection_, PlanStatus::projected);
  }
  const auto e = walking_edge(r, dir_);
  if (!e) return finish(x, PlanStatus::stalled);
  const Vec2 end = dir_ > 0 ? e->b : e->a;
  if (e->index == projection_edge_ && dot(projection_ - x, end - x) >= 0.0 &&
      distance(projection_, x) <= max_step) {
    path_ += distance(projection_, x);
    return finish(projection_, PlanStatus::projected);
  }
  return move(r, x + std::min(max_step, distance(end, x)) * unit(end - x));
}

TangentBug::Free TangentBug::free_distance(const SensorReading& r, Vec2 u, double limit) const {
  const Vec2 x = r.position;
  // A wall the robot touches may block the direction at once: free space is on the left of
  // each boundary edge; at a vertex, of both edges (convex corner) or either (reflex).
  const auto left = [&](const ContactEdge& e) { return cross(unit(e.b - e.a), u) >= -1e-12; };
  const ContactEdge* in = nullptr;
  const ContactEdge* out = nullptr;
  for (const ContactEdge& c : r.contacts) {
    if (distance(c.b, x) <= p_.tolerance)
      in = &c;
    else if (distance(c.a, x) <= p_.tolerance)
      out = &c;
    else if (!left(c))
      return Free{0.0, c.ring, std::nullopt};
  }
  if (in && out) {
    const bool convex = cross(x - in->a, out->b - x) > 0.0;
    const bool free = convex ? (left(*in) && left(*out)) : (left(*in) || left(*out));
    if (!free) return Free{0.0, in->ring, std::nullopt};
  } else if (in || out) {
    const ContactEdge& c = in ? *in : *out;
    if (!left(c)) return Free{0.0, c.ring, std::nullopt};
  }
  // Then the nearest sensed piece the ray crosses beyond the robot's own position.
  Free f{kInf, std::nullopt, std::nullopt};
  for (std::size_t k = 0; k < r.visible.pieces.size(); ++k) {
    const Vec2 a = r.visible.pieces[k].a, s = r.visible.pieces[k].b - a;
    const double denom = cross(u, s);
    if (std::fabs(denom) <= 1e-12 * norm(s)) continue;  // parallel: running along it
    const double t = cross(a - x, s) / denom;
    const double v = cross(a - x, u) / denom;
    if (t > p_.tolerance && v >= -1e-12 && v <= 1.0 + 1e-12 && t < f.distance) {
      f.distance = t;
      f.blocker = r.piece_rings[k];
      f.piece = k;
    }
  }
  if (f.distance > limit) return Free{kInf, std::nullopt, std::nullopt};
  return f;
}

std::optional<ContactEdge> TangentBug::walking_edge(const SensorReading& r, int dir) const {
  for (const ContactEdge& c : r.contacts) {
    if (distance(dir > 0 ? c.b : c.a, r.position) > p_.tolerance) return c;
  }
  return std::nullopt;
}

void TangentBug::remember(const ContactEdge& e) {
  memory_[e.ring].edges[e.index] = {e.a, e.b};
}

bool TangentBug::goal_inside(std::uint32_t ring) const {
  const RingMemory& m = memory_.at(ring);
  std::vector<Vec2> polygon;
  for (const auto& [index, edge] : m.edges)
    polygon.push_back(edge.first);
  const bool inside = inside_ring(polygon, goal_);
  return ring == 0 ? !inside : inside;  // the outer ring holds what lies outside it
}

std::pair<Vec2, std::uint32_t> TangentBug::closest_on_ring(std::uint32_t ring) const {
  const RingMemory& m = memory_.at(ring);
  std::pair<Vec2, std::uint32_t> best{goal_, 0};
  double d = kInf;
  for (const auto& [index, edge] : m.edges) {
    const Vec2 q = project_to_segment(goal_, edge.first, edge.second).point;
    if (distance(q, goal_) < d) {
      d = distance(q, goal_);
      best = {q, index};
    }
  }
  return best;
}

double TangentBug::arc(std::uint32_t ring, Vec2 x, std::uint32_t i, Vec2 q, std::uint32_t j,
                       int dir) const {
  const RingMemory& m = memory_.at(ring);
  const std::uint32_t n = m.size;
  const auto edge = [&](std::uint32_t k) { return m.edges.at(k); };
  const auto [ai, bi] = edge(i);
  const auto [aj, bj] = edge(j);
  if (dir > 0) {
    if (i == j && dot(q - x, bi - ai) >= 0.0) return distance(q, x);
    double sum = distance(bi, x);
    for (std::uint32_t k = (i + 1) % n, steps = 0; k != j && steps < n; k = (k + 1) % n, ++steps) {
      sum += distance(edge(k).first, edge(k).second);
    }
    return sum + distance(q, aj);
  }
  if (i == j && dot(q - x, bi - ai) <= 0.0) return distance(q, x);
  double sum = distance(x, ai);
  for (std::uint32_t k = (i + n - 1) % n, steps = 0; k != j && steps < n;
       k = (k + n - 1) % n, ++steps) {
    sum += distance(edge(k).first, edge(k).second);
  }
  return sum + distance(bj, q);
}

}  // namespace covsim
