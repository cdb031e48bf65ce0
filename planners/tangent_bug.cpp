#include "planners/tangent_bug.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/environment.hpp"

namespace covsim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
Vec2 unit(Vec2 v) {
  const double n = norm(v);
  return n > 0.0 ? v / n : Vec2{0, 0};
}
}  // namespace

std::string_view to_string(TangentBug::Mode m) {
  switch (m) {
    case TangentBug::Mode::motion_to_goal:
      return "motion_to_goal";
    case TangentBug::Mode::follow:
      return "follow";
    case TangentBug::Mode::leave:
      return "leave";
    case TangentBug::Mode::to_projection:
      return "to_projection";
    case TangentBug::Mode::to_closest:
      return "to_closest";
    case TangentBug::Mode::settle:
      return "settle";
    case TangentBug::Mode::done:
      return "done";
  }
  return "unknown";
}

TangentBugParams TangentBugParams::for_environment(double diameter, double boundary_length) {
  return TangentBugParams{1e-9 * diameter, 1e-9 * diameter, 10.0 * (boundary_length + diameter),
                          0.0};
}

void TangentBug::set_goal(Vec2 goal) {
  goal_ = goal;
  mode_ = Mode::motion_to_goal;
  status_ = PlanStatus::moving;
  h_prev_ = bound_ = kInf;
  heading_.reset();
  path_ = 0.0;
  last_position_.reset();
  aim_.reset();
  moved_ = false;
  idle_steps_ = 0;
  episodes_.clear();
  engaged_.clear();
  loops_ = recoveries_ = 0;
  leave_length_ = 0.0;
}

void TangentBug::move_goal(Vec2 goal) {
  if (mode_ == Mode::done || mode_ == Mode::to_projection || mode_ == Mode::settle)
    return set_goal(goal);
  const double shift = distance(goal, goal_);
  goal_ = goal;
  goal_behind_wall_ = false;
  h_prev_ += shift;
  bound_ += shift;
  d_followed_ += shift;
  idle_steps_ = 0;
  moved_ = false;  // the way back may be the way to the moved goal
}

PlanStep TangentBug::finish(Vec2 at, PlanStatus s) {
  mode_ = Mode::done;
  status_ = s;
  return PlanStep{at, s};
}

PlanStep TangentBug::move_toward(Vec2 x, Vec2 p, double max_step) {
  aim_ = p;
  const double d = distance(x, p);
  return PlanStep{d <= max_step ? p : x + (max_step / d) * (p - x), PlanStatus::moving};
}

bool TangentBug::retraces(Vec2 x, Vec2 p) const {
  if (!moved_ || !motion_) return false;
  // Back within a fifth of a radian of the way it came (a way that ends a step on no farther
  // than a fifth of a step from it is the same ground), or the noise of it. (Within the noise
  // a step back is no walk back: round a noisy wall's end, say.)
  const Vec2 v = p - x;
  const double back = -dot(v, *motion_);
  return back > p_.noise_margin && std::fabs(cross(*motion_, v)) <= 1e3 * p_.tolerance + 0.2 * back;
}

bool TangentBug::against_trail(Vec2 x, Vec2 p) const {
  const double length = distance(x, p);
  if (trail_.size() < 2 || !(length > p_.tolerance) || !(step_ > 0.0)) return false;
  const Vec2 u = (p - x) / length;
  const double width = 2.0 * step_ + p_.noise_margin;
  // The parts of the trail near the way (their boxes within `width` of the way's box), each
  // walked with the way (along) or against it.
  Box near;
  near.add(x);
  near.add(p);
  near.lo = near.lo - Vec2{width, width};
  near.hi = near.hi + Vec2{width, width};
  struct Part {
    Vec2 a, b;
    bool against;
  };
  std::vector<Part> parts;
  for (std::size_t k = 0; k + 1 < trail_.size(); ++k) {
    const Vec2 a = trail_[k], b = trail_[k + 1];
    if (std::max(a.x, b.x) < near.lo.x || std::min(a.x, b.x) > near.hi.x ||
        std::max(a.y, b.y) < near.lo.y || std::min(a.y, b.y) > near.hi.y)
      continue;
    parts.push_back({a, b, dot(b - a, u) < 0.0});
  }
  if (std::none_of(parts.begin(), parts.end(), [](const Part& q) { return q.against; }))
    return false;
  // Points along the way, at most 32, half a step apart on a short way.
  const int samples = static_cast<int>(std::min(32.0, std::ceil(2.0 * length / step_)));
  const double spacing = length / samples;
  double beside = 0.0;  // how much of the way runs back beside the trail
  for (int i = 1; i <= samples; ++i) {
    const Vec2 q = x + (i * spacing) * u;
    double against = kInf, along = kInf;  // squared distances
    for (const Part& part : parts) {
      const Vec2 f = project_to_segment(q, part.a, part.b).point;
      const double d2 = dot(f - q, f - q);
      double& best = part.against ? against : along;
      best = std::min(best, d2);
    }
    if (against <= width * width && std::sqrt(against) < std::sqrt(along) - p_.tolerance)
      beside += spacing;
  }
  return beside >= step_;
}

PlanStep TangentBug::toward(const SensorReading& r, Vec2 p, double max_step) {
  PlanStep s = move_toward(r.position, p, max_step);
  if (by_touch(r) || p_.noise_margin > 0.0) return s;
  // The view changes at a vertex the way passes through (a corner passed on the way to the
  // wall behind it): Kamon et al.'s robot decides again there, and a step past it might
  // have to come back.
  const Vec2 x = r.position;
  double reach = distance(x, s.next);
  for (const SensedPiece& piece : r.visible().pieces) {
    for (const Vec2 v : {piece.a, piece.b}) {
      const double d = distance(x, v);
      if (d <= p_.tolerance || d >= reach - p_.tolerance) continue;
      if (distance(project_to_segment(v, x, s.next).point, v) > p_.tolerance) continue;
      s.next = v;
      reach = d;
    }
  }
  return s;
}

void TangentBug::resume_motion_to_goal() {
  mode_ = Mode::motion_to_goal;
  h_prev_ = kInf;
}

PlanStep TangentBug::step(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  step_ = max_step;
  if (mode_ == Mode::done) return PlanStep{x, status_};
  // A range reading taken elsewhere (the sensor reads less often than the robot steps, or
  // the last reading was lost) shows the view from there: its discontinuities, shadows and
  // range would mislead every test of the algorithm made from here.
  const bool stale = !by_touch(r) && beyond(r.origin, x, p_.tolerance);
  // Bookkeeping from where the robot actually is (the world may have stopped a motion).
  if (last_position_) {
    const double moved = distance(*last_position_, x);
    path_ += moved;
    // Waiting for a reading is not stalling.
    if (moved > p_.tolerance || !stale) idle_steps_ = moved > p_.tolerance ? 0 : idle_steps_ + 1;
    if (moved > p_.tolerance) {
      motion_ = (x - *last_position_) / moved;
      moved_ = true;
      if (mode_ == Mode::follow) {
        trail_.push_back(x);
        if (trail_.size() > kTrail) trail_.erase(trail_.begin());
      }
    }
  }
  last_position_ = x;
  if (path_ > p_.path_budget || idle_steps_ > kMaxIdleSteps) return finish(x, PlanStatus::stalled);
  if (distance(goal_, x) <= p_.tolerance) return finish(goal_, PlanStatus::reached);
  // On a stale reading, on toward the point the last decision chose, from where that
  // reading was taken (the way there was free in it); decide again on the next fresh one.
  if (stale) {
    if (aim_ && beyond(*aim_, x, p_.tolerance)) return move_toward(x, *aim_, max_step);
    return PlanStep{x, PlanStatus::moving};
  }
  aim_.reset();
  // A mode change decides again at once; a handful always settles on a motion.
  for (int hop = 0; hop < 8; ++hop) {
    Decision d;
    switch (mode_) {
      case Mode::motion_to_goal:
        d = motion_to_goal(r, max_step);
        break;
      case Mode::follow:
        d = by_touch(r) ? follow_by_touch(r, max_step) : follow(r, max_step);
        break;
      case Mode::leave:
        d = leave(r, max_step);
        break;
      case Mode::to_projection:
      case Mode::to_closest:
        d = walk_on(r, max_step);
        break;
      case Mode::settle:
        d = settle(r, max_step);
        break;
      case Mode::done:
        return PlanStep{x, status_};
    }
    if (d) return *d;
  }
  return PlanStep{x, PlanStatus::moving};
}

TangentBug::Decision TangentBug::motion_to_goal(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  // An obstacle gone round before that encloses the goal: project at once when touching it,
  // or when its point closest to the goal is in sight (else motion to goal may take the
  // robot along that obstacle to where it touches it, and the walk to the projection back).
  for (std::size_t k = 0; k < known_.size(); ++k) {
    if (!known_[k].encloses(goal_)) continue;
    if (!r.contacts.empty() && known_[k].on_boundary(x, loop_tolerance()))
      return walk_to(r, k, Mode::to_projection);
    const Vec2 p = known_[k].closest(goal_).point;
    const double d = distance(x, p);
    if (!by_touch(r) && d > p_.tolerance && d <= r.range &&
        free_ray(r, (p - x) / d, p_.tolerance).distance >= d - p_.tolerance)
      return walk_to(r, k, Mode::to_projection);
  }
  // The way to the goal open within the range, with a margin: the goal is a node, and every
  // other node (a point of the sensed boundary, at least the margin m from the way) has a
  // heuristic distance above the goal's by at least 2m²/d(x, goal), far beyond rounding, so
  // the goal is the best node. Decided without the visible boundary, as the full choice
  // below would decide.
  if (r.open_toward(goal_, 1e3 * p_.tolerance)) {
    const double dg = distance(goal_, x);
    if (dg <= h_prev_ + p_.tolerance) {
      h_prev_ = dg;
      heading_ = goal_;
      return move_toward(x, goal_, max_step);
    }
  }
  const std::vector<TangentNode> nodes =
      tangent_nodes(r, goal_, bound_ - p_.progress, p_.tolerance);
  // Not a node back along the way the robot came: going there walks the same ground twice.
  // (Kamon et al.'s robot, moving continuously, turns back at the first instant such a node
  // is the best: it stands at a local minimum, and follows the boundary from there.)
  const TangentNode* best = nullptr;
  for (const TangentNode& n : nodes) {
    if (retraces(x, n.point)) continue;
    if (best == nullptr || n.heuristic < best->heuristic) best = &n;
  }
  // The heuristic distance must not increase: moving toward a node lowers it by the step,
  // and a better node lowers it more.
  if (best != nullptr && best->heuristic <= h_prev_ + p_.tolerance) {
    h_prev_ = best->heuristic;
    heading_ = best->point;
    if (!best->is_goal && (engaged_.empty() || beyond(engaged_.back(), best->point, p_.tolerance)))
      engaged_.push_back(best->point);
    return toward(r, best->point, max_step);
  }
  // A local minimum: follow the boundary in the way.
  const FreeRay f = free_ray(r, unit(goal_ - x), p_.tolerance);
  if (f.blocked_at) return begin_following(r, *f.blocked_at);
  // Nothing sensed in the way, yet no node: cannot happen (the goal is a node then), but
  // head for the goal rather than stand still.
  heading_ = goal_;
  return move_toward(x, goal_, std::min(max_step, f.distance));
}

TangentBug::Decision TangentBug::begin_following(const SensorReading& r, Vec2 blocked_at) {
  const Vec2 x = r.position;
  for (std::size_t k = 0; k < known_.size(); ++k) {
    if (known_[k].on_boundary(blocked_at, loop_tolerance()) && known_[k].encloses(goal_))
      return walk_to(r, k, Mode::to_projection);
  }
  // The direction that continues the motion (Kamon et al.): toward the point last headed
  // for while it lies ahead; standing on it, the direction of the last step that moved;
  // only a robot that has never moved takes the goal's. Between two equally good ones, the
  // one whose end lies nearer the goal.
  const bool on_the_way = heading_ && distance(*heading_, x) > p_.tolerance;
  const Vec2 ref = on_the_way ? unit(*heading_ - x) : motion_ ? *motion_ : unit(goal_ - x);
  int dir = 0;
  double best_score = -kInf, best_end = kInf;
  const auto consider = [&](int d, Vec2 end) {
    if (distance(end, x) <= p_.tolerance) return;
    const double score = dot(unit(end - x), ref), to_goal = distance(end, goal_);
    if (score > best_score + 1e-9 ||
        (std::fabs(score - best_score) <= 1e-9 && to_goal < best_end)) {
      best_score = score;
      best_end = to_goal;
      dir = d;
    }
  };
  Vec2 boundary = x;
  std::vector<SensedChain> chains;
  if (!by_touch(r)) chains = sensed_chains(r, p_.tolerance);
  if (chains.empty()) {
    // Touching, with nothing seen: along the wall, to the touched edge's end either way.
    for (int d : {1, -1}) {
      if (const auto e = walking_edge(r, d, p_.tolerance)) consider(d, d > 0 ? e->b : e->a);
    }
    d_followed_ = distance(x, goal_);
  } else {
    // The blocking obstacle: the stretch of sensed boundary holding the point in the way;
    // its LTG nodes are that stretch's ends.
    std::size_t best = 0;
    double near = kInf;
    for (std::size_t k = 0; k < chains.size(); ++k) {
      const double d = closest_place(chains[k].points, blocked_at).distance;
      if (d < near) near = d, best = k;
    }
    const SensedChain& c = chains[best];
    episodes_.push_back({x, blocked_at});
    if (c.closed) return loop_closed(r, RecordedObstacle(c.points, 1, p_.tolerance));
    // Kamon et al. compare the local tangents with the motion; covsim the way to the next
    // point of the stretch each way, which is the tangent when the robot stands on the wall,
    // among the ways that have a point to head for (TangentBug::ahead). When the stretch ends
    // where the robot stands (the wall it touches, seen edge-on, shows only the point under
    // it): along that wall, as by touch. Only when every way forward goes back over the last
    // step, that way: rather that than stop.
    bool along_wall = false;
    const bool on_it = closest_place(c.points, x).distance <= loop_tolerance();
    // A way whose stretch, past the point headed for, runs back along the robot's last step
    // (a corner just ahead, then the wall it came along) is taken only if no other is.
    const auto leads_back = [&](const std::vector<Vec2>& stretch) {
      return std::any_of(stretch.begin(), stretch.end(), [&](Vec2 q) { return retraces(x, q); });
    };
    for (int pass = 0; pass < 3 && dir == 0; ++pass) {
      const bool keep_on = pass < 2;
      for (int d : {1, -1}) {
        std::vector<Vec2> stretch = c.points;
        if (d < 0) std::reverse(stretch.begin(), stretch.end());
        const std::optional<Ahead> a =
            ahead(stretch, blocked_at, x, d, keep_on, 2.0 * step_ + p_.noise_margin);
        if (!a) continue;
        const PolylinePlace at = closest_place(stretch, a->point);
        if (pass == 0 && leads_back({stretch.begin() + static_cast<std::ptrdiff_t>(at.segment + 1),
                                     stretch.end()}))
          continue;
        consider(d, a->next);
      }
      if (dir == 0 && on_it && pass > 0) {
        for (int d : {1, -1}) {
          const auto e = walking_edge(r, d, p_.tolerance);
          if (e && !(keep_on && retraces(x, d > 0 ? e->b : e->a))) consider(d, d > 0 ? e->b : e->a);
        }
        along_wall = dir != 0;
      }
    }
    const PolylinePlace at = closest_place(c.points, blocked_at);
    boundary = at.point;
    if (along_wall) {
      const auto e = walking_edge(r, dir, p_.tolerance);
      trace_direction_ = unit((dir > 0 ? e->b : e->a) - x);
    } else if (dir != 0 && at.segment + 1 < c.points.size()) {
      trace_direction_ =
          static_cast<double>(dir) * unit(c.points[at.segment + 1] - c.points[at.segment]);
    }
    // With noise, d_reach and d_followed each err by the noise: a leave must beat the last
    // one (the bound) by the progress, so that leaves are finitely many.
    d_followed_ = p_.noise_margin > 0.0 ? bound_ : kInf;
  }
  if (dir == 0) return finish(x, PlanStatus::stalled);  // nothing to follow
  if (chains.empty()) episodes_.push_back({x, x});
  mode_ = Mode::follow;
  goal_behind_wall_ = false;
  dir_ = dir;
  start_ = x;
  walked_ = 0.0;
  head_ = anchor_ = boundary;
  trace_.assign(1, boundary);
  trail_.assign(1, x);
  traced_ = 0.0;
  trace_path_ = path_;
  return std::nullopt;
}

std::optional<SensedChain> TangentBug::followed_chain(const SensorReading& r) const {
  std::vector<SensedChain> chains = sensed_chains(r, p_.tolerance);
  if (chains.empty()) return std::nullopt;
  std::size_t best = 0;
  double near = kInf;
  for (std::size_t k = 0; k < chains.size(); ++k) {
    const double d = closest_place(chains[k].points, head_).distance;
    if (d < near) near = d, best = k;
  }
  // The node last headed for out of sight (seen edge-on, it dropped out of its stretch, whose
  // rest is still in sight): the stretch through the point before it, unless another passes
  // nearer the node (else a neighbouring obstacle's stretch is taken for the followed one,
  // and the robot circles that obstacle for ever).
  if (near > loop_tolerance()) {
    for (std::size_t k = 0; k < chains.size(); ++k) {
      const double d = closest_place(chains[k].points, anchor_).distance;
      if (d < near) near = d, best = k;
    }
  }
  SensedChain c = std::move(chains[best]);
  if (dir_ < 0) std::reverse(c.points.begin(), c.points.end());
  return c;
}

double TangentBug::record_drift() const {
  if (!(p_.drift > 0.0) || !(step_ > 0.0)) return 0.0;
  return kDriftDeviations * p_.drift * std::sqrt(std::max(0.0, path_ - trace_path_) / step_);
}

bool TangentBug::record(const SensedChain& c) {
  const PolylinePlace at = closest_place(c.points, trace_.back());
  // Back where it began within what the frame may have drifted meanwhile (an odometry's):
  // else a robot goes round and round an obstacle it has gone round.
  const double eps = loop_tolerance() + record_drift();
  const Vec2 began = trace_.front();
  std::vector<Vec2> ahead{at.point};
  ahead.insert(ahead.end(), c.points.begin() + static_cast<std::ptrdiff_t>(at.segment + 1),
               c.points.end());
  // The stretch may begin off the record's end: the boundary between was not seen (it lay
  // hidden, or out of range, when the stretch passed it). The record bridges it, and does not
  // close on the bridge: a loop is what the sensor saw come back to where it began.
  const bool bridge = at.distance > eps;
  for (Vec2 q : ahead) {
    const Vec2 p = trace_.back();
    if (!beyond(q, p, p_.tolerance)) continue;
    // Back where the record began, going the same way: round the obstacle. (The other face
    // of a thin wall passes as near, the other way.)
    const Vec2 foot = project_to_segment(began, p, q).point;
    const bool seen = !(bridge && trace_.size() > 0 && q == ahead.front());
    if (seen && traced_ > 4.0 * eps && within(foot, began, eps) &&
        dot(q - p, trace_direction_) > 0.0) {
      trace_.push_back(foot);
      return true;
    }
    traced_ += distance(p, q);
    trace_.push_back(q);
  }
  return false;
}

std::optional<TangentBug::Ahead> TangentBug::ahead(const std::vector<Vec2>& stretch, Vec2 from,
                                                   Vec2 x, int dir, bool keep_on, double by) const {
  // Seen from the robot, the stretch's points turn one way (counter-clockwise in the walking
  // order of direction +1): the first that lies half a turn or more from the first direction
  // ends the part it can head for straight with the stretch before it on the obstacle's side.
  // (From a corner it stands on, the end of a stretch that wraps round it lies back along
  // the wall it came by.)
  // From `from`'s place, or from the robot's own if it stands within `by` of the stretch
  // farther on: the part before lies behind it (at a stretch's end the robot sees the
  // stretch run back from its feet; beside a wall it reached near one end, the wall runs
  // back past the point it is blocked at).
  PolylinePlace at = closest_place(stretch, from);
  const PolylinePlace own = closest_place(stretch, x);
  if (own.distance <= std::max(loop_tolerance(), by) &&
      (own.segment > at.segment ||
       (own.segment == at.segment &&
        distance(stretch[own.segment], own.point) > distance(stretch[at.segment], at.point))))
    at = own;
  std::vector<Vec2> points{at.point};
  for (std::size_t k = at.segment + 1; k < stretch.size(); ++k) {
    if (beyond(stretch[k], points.back(), p_.tolerance)) points.push_back(stretch[k]);
  }
  std::optional<Vec2> first, next;
  std::vector<Ahead> out;  // the points it may head for, nearest first
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec2 w = points[k] - x;
    if (norm(w) <= p_.tolerance) continue;
    if (!first) first = unit(w);
    if (!next && (k > 0 || points.size() == 1)) next = points[k];
    const double turn = static_cast<double>(dir) * cross(*first, w);
    const bool within_half_turn =
        turn > p_.tolerance || (turn >= -p_.tolerance && dot(*first, w) > 0.0);
    if (!within_half_turn) break;
    if (keep_on && retraces(x, points[k])) continue;  // a point farther on may not: on to it
    // The stretch's point before it: the anchor that finds the stretch again when the point
    // drops out of sight (TangentBug::followed_chain).
    Vec2 before = k > 0 ? points[k - 1] : stretch[at.segment];
    if (k == 0 && !beyond(before, points[0], p_.tolerance) && at.segment > 0)
      before = stretch[at.segment - 1];
    out.push_back(Ahead{points[k], before, next.value_or(points[k])});
  }
  // The farthest, unless the way there runs back beside the way the robot followed the
  // boundary so far (from just past a corner where the stretch wrapped round the robot, its
  // far end lies back under the wall it came along).
  for (auto a = out.rbegin(); a != out.rend(); ++a) {
    if (!keep_on || mode_ != Mode::follow || !against_trail(x, a->point)) return *a;
  }
  return std::nullopt;
}

PlanStep TangentBug::chase(const SensorReading& r, const SensedChain& c, double max_step,
                           bool keep_on) {
  const Vec2 x = r.position;
  const double by = 2.0 * step_ + p_.noise_margin;
  std::optional<Ahead> a = ahead(c.points, head_, x, dir_, keep_on, by);
  // Only back the way it came: rather that than stand still.
  if (!a && keep_on) a = ahead(c.points, head_, x, dir_, false, by);
  if (!a) {
    // Nothing ahead beyond where the robot stands: along the wall it touches, if any.
    const auto e = walking_edge(r, dir_, p_.tolerance);
    if (!e) return PlanStep{x, PlanStatus::moving};
    head_ = anchor_ = dir_ > 0 ? e->b : e->a;
    return walk(r, max_step, std::nullopt);
  }
  head_ = a->point;
  anchor_ = a->before;
  heading_ = a->point;
  return toward(r, a->point + p_.noise_margin * unit(a->point - x), max_step);
}

TangentBug::Decision TangentBug::follow(const SensorReading& r, double max_step) {
  const std::optional<SensedChain> c = followed_chain(r);
  if (!c) return finish(r.position, PlanStatus::stalled);  // lost sight of every wall
  if (c->closed) return loop_closed(r, RecordedObstacle(c->points, dir_, p_.tolerance));
  // The goal on the visible followed boundary: a point in sight, whatever a touched wall
  // grazing the way to it says.
  if (closest_place(c->points, goal_).distance <= p_.tolerance) {
    heading_ = goal_;
    return move_toward(r.position, goal_, max_step);
  }
  // d_followed: the followed boundary as sensed now.
  for (std::size_t k = 0; k + 1 < c->points.size(); ++k) {
    const Vec2 q = project_to_segment(goal_, c->points[k], c->points[k + 1]).point;
    d_followed_ = std::min(d_followed_, distance(q, goal_) + p_.noise_margin);
  }
  if (c->points.size() == 1) d_followed_ = std::min(d_followed_, distance(c->points[0], goal_));
  // Not back over the last step (that ground was just walked), nor behind a wall the robot
  // touches (contacts are exact: range noise may show a way there).
  const Vec2 x = r.position;
  const ReachPoint reach = reach_point(r, goal_, &*c, p_.tolerance, [&](Vec2 p) {
    return !retraces(x, p) && (r.contacts.empty() || !beyond(p, x, p_.tolerance) ||
                               free_ray(r, unit(p - x), p_.tolerance).distance > 0.0);
  });
  // The goal in sight counts even when it lies on the followed boundary (d_followed 0). The
  // reach point is sensed too: with noise it must be nearer beyond the noise of both.
  const bool in_sight =
      reach.distance == 0.0 &&
      (!goal_behind_wall_ || free_ray(r, unit(goal_ - r.position), p_.tolerance).distance >=
                                 distance(r.position, goal_) + p_.noise_margin);
  if (reach.distance + p_.noise_margin < d_followed_ - p_.progress || in_sight) {
    bound_ = d_followed_;  // what every later node and leave must beat
    leave_to_ = reach.point;
    leave_length_ += distance(r.position, leave_to_);
    mode_ = Mode::leave;
    return std::nullopt;
  }
  if (record(*c)) return loop_closed(r, RecordedObstacle(trace_, dir_, p_.tolerance));
  return chase(r, *c, max_step, true);
}

TangentBug::Decision TangentBug::follow_by_touch(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  const ReachPoint reach =
      reach_point(r, goal_, nullptr, p_.tolerance, [&](Vec2 p) { return !retraces(x, p); });
  if (reach.distance < d_followed_ - p_.progress) {
    bound_ = d_followed_;
    leave_to_ = reach.point;
    leave_length_ += distance(x, leave_to_);
    mode_ = Mode::leave;
    return std::nullopt;
  }
  // The point under the robot counts after the leave test, so that it can leave where it
  // stands.
  d_followed_ = std::min(d_followed_, distance(x, goal_));
  // The robot walks on the boundary and stops at every vertex: its positions are the record.
  if (beyond(x, trace_.back(), p_.tolerance)) trace_.push_back(x);
  const double drifted = record_drift();
  if (walked_ > std::max(p_.tolerance, 4.0 * drifted) &&
      distance(x, start_) <= p_.tolerance + drifted)
    return loop_closed(r, RecordedObstacle(trace_, dir_, p_.tolerance));
  return walk(r, max_step, start_);
}

TangentBug::Decision TangentBug::leave(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  const double d = distance(x, leave_to_);
  // Arrived (under drift, within the jitter of a step: the point was set in the frame of a
  // step before), or a wall the robot touches stands in the way (possible only with noise).
  if (d <= p_.tolerance + kDriftDeviations * p_.drift ||
      free_ray(r, (leave_to_ - x) / d, p_.tolerance).distance == 0.0) {
    if (d > p_.tolerance && leave_to_ == goal_ && p_.noise_margin > 0.0) {
      // The goal looked free and lies just beyond a wall: no leave after all. The episode
      // and its record go on, the goal in sight now only with the way free past it by the
      // margin (else the robot heads for it again from every point of the boundary and
      // never closes the loop).
      goal_behind_wall_ = true;
      mode_ = Mode::follow;
      return std::nullopt;
    }
    resume_motion_to_goal();
    return std::nullopt;
  }
  heading_ = leave_to_;
  return move_toward(x, leave_to_, max_step);
}

TangentBug::Decision TangentBug::loop_closed(const SensorReading& r, RecordedObstacle obstacle) {
  ++loops_;
  known_.push_back(std::move(obstacle));
  if (known_.back().encloses(goal_)) return walk_to(r, known_.size() - 1, Mode::to_projection);
  ++recoveries_;
  return walk_to(r, known_.size() - 1, Mode::to_closest);
}

TangentBug::Decision TangentBug::walk_to(const SensorReading& r, std::size_t known, Mode mode) {
  const RecordedObstacle& o = known_[known];
  obstacle_ = known;
  mode_ = mode;
  straight_ = false;
  target_ = o.closest(goal_);
  // The shorter way round, from the recorded point nearest the robot.
  const RingPlace here = o.closest(r.position);
  dir_ = o.arc(here, target_, 1) <= o.arc(here, target_, -1) ? 1 : -1;
  head_ = anchor_ = here.point;
  return std::nullopt;
}

void TangentBug::reanchor(const SensorReading& r) {
  const double reach = record_drift() + loop_tolerance();
  const Vec2 c = target_.point;
  std::optional<Vec2> best;
  double least = kInf;
  for (const SensedPiece& p : r.visible().pieces) {
    // The stretch of the piece within `reach` of c: t in [t0, t1] where |a + t d - c| <= reach.
    const Vec2 d = p.b - p.a;
    const double dd = norm2(d);
    if (!(dd > 0.0)) continue;
    const double mid = dot(c - p.a, d) / dd;
    const double off2 = norm2(p.a + mid * d - c);
    if (off2 > reach * reach) continue;
    const double half = std::sqrt((reach * reach - off2) / dd);
    const double lo = std::max(0.0, mid - half), hi = std::min(1.0, mid + half);
    if (lo > hi) continue;
    const double t = std::clamp(dot(goal_ - p.a, d) / dd, lo, hi);
    const Vec2 q = p.a + t * d;
    if (distance(q, goal_) < least) {
      least = distance(q, goal_);
      best = q;
    }
  }
  if (best) target_.point = *best;
}

TangentBug::Decision TangentBug::walk_on(const SensorReading& r, double max_step) {
  if (p_.drift > 0.0) reanchor(r);
  const Vec2 x = r.position, target = target_.point;
  // With noise the recorded point may lie off the wall, by more than the noise where it is
  // the nearest of many noisy points: near it, or touching where the straight way to it
  // stopped, will do (the settling approach and descent, by touch, do the rest).
  if (within(x, target, p_.tolerance + 10.0 * p_.noise_margin) ||
      (!r.contacts.empty() && straight_)) {
    straight_ = false;
    if (mode_ == Mode::to_projection) {
      mode_ = Mode::settle;
      seeking_ = sought_ = false;
      return std::nullopt;
    }
    // The way toward the goal is free here: motion to goal again, no bound from before.
    resume_motion_to_goal();
    bound_ = kInf;
    return std::nullopt;
  }
  if (by_touch(r)) return walk(r, max_step, target);
  const double d = distance(x, target);
  const Vec2 u = (target - x) / d;
  // In sight (within range, nothing in the way): straight there. Else on round the obstacle,
  // as when following it.
  if (d <= r.range + p_.noise_margin &&
      free_ray(r, u, p_.tolerance).distance >= d - p_.tolerance - p_.noise_margin) {
    heading_ = target;
    straight_ = true;
    return move_toward(x, target + p_.noise_margin * u, max_step);
  }
  straight_ = false;
  const std::optional<SensedChain> c = followed_chain(r);
  if (!c) return finish(x, PlanStatus::stalled);
  // The shorter way round from where the loop closed, back over the last step only when that
  // is the way: the one turn the walk to the projection makes.
  return chase(r, *c, max_step, true);
}

TangentBug::Decision TangentBug::settle(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  const FreeRay toward = free_ray(r, unit(goal_ - x), p_.tolerance);
  if (r.contacts.empty()) {
    // Short of the wall (noise): straight at the goal until touching.
    if (toward.blocked_at)
      return move_toward(x, goal_, std::min(max_step, toward.distance + p_.noise_margin));
  } else {
    const RecordedObstacle& o = known_[obstacle_];
    const double recorded = distance(target_.point, goal_);
    const double enough = recorded + p_.noise_margin + p_.tolerance;
    if (seeking_) {
      // By touch toward the record's closest point, until there or as near the goal.
      if (walked_ < seek_arc_ - p_.noise_margin && distance(x, goal_) > recorded)
        return walk(r, max_step, std::nullopt);
      seeking_ = false;
    }
    // Along the touched wall while the goal gets nearer: contacts are exact, so this ends at
    // the wall's point closest to the goal.
    Vec2 best = x;
    double nearest = distance(x, goal_) - p_.tolerance;
    for (int d : {1, -1}) {
      const auto e = walking_edge(r, d, p_.tolerance);
      if (!e) continue;
      const Vec2 q = project_to_segment(goal_, e->a, e->b).point;
      if (distance(q, goal_) < nearest) {
        nearest = distance(q, goal_);
        best = q;
      }
    }
    if (!(best == x)) return move_toward(x, best, max_step);
    if (toward.distance == 0.0) {
      // A touched wall faces the goal: nothing of Ω near lies nearer it. With noise this may
      // be a local minimum on another face than the record's closest point (the end or the
      // far face of a wall thinner than the noise): unless it is as near the goal as that
      // point and the record joins the two without going round anything, walk there once
      // by touch, the shorter way round the record, and slide again.
      const RingPlace here = o.closest(x);
      const int way = o.arc(here, target_, 1) <= o.arc(here, target_, -1) ? 1 : -1;
      const double arc = o.arc(here, target_, way);
      const bool elsewhere =
          arc > distance(here.point, target_.point) + 2.0 * p_.noise_margin + p_.tolerance;
      if (!sought_ && (distance(x, goal_) > enough || elsewhere)) {
        dir_ = way;
        seeking_ = sought_ = true;
        seek_arc_ = arc;
        walked_ = 0.0;
        return walk(r, max_step, std::nullopt);
      }
      if (distance(x, goal_) <= enough) return finish(x, PlanStatus::projected);
    }
  }
  return forget_record();
}

TangentBug::Decision TangentBug::forget_record() {
  // The record was wrong (noise): forget it, and motion to goal again.
  ++recoveries_;
  known_.erase(known_.begin() + static_cast<std::ptrdiff_t>(obstacle_));
  resume_motion_to_goal();
  bound_ = kInf;
  return std::nullopt;
}

PlanStep TangentBug::walk(const SensorReading& r, double max_step, std::optional<Vec2> stop) {
  const Vec2 x = r.position;
  const auto e = walking_edge(r, dir_, p_.tolerance);
  if (!e) return finish(x, PlanStatus::stalled);
  const Vec2 end = dir_ > 0 ? e->b : e->a;
  Vec2 target = end;
  double dt = distance(end, x);
  const auto consider = [&](Vec2 w) {
    const double dw = distance(w, x);
    if (dw <= p_.tolerance || dw >= dt) return;
    if (distance(project_to_segment(w, x, end).point, w) > p_.tolerance) return;
    target = w;
    dt = dw;
  };
  // The edge's point closest to the goal: where d(x, goal) is least along it.
  consider(project_to_segment(goal_, e->a, e->b).point);
  if (stop) consider(*stop);
  const PlanStep s = move_toward(x, target, max_step);
  walked_ += distance(x, s.next);
  return s;
}

PlannerEntry tangent_bug_entry() {
  PlannerEntry e;
  e.name = "tangent_bug";
  e.reads_range = true;
  e.senses_only = true;
  e.description =
      "TangentBug (Kamon et al. 1998) with target projection; range sensor of any range";
  e.make = [](const PlannerContext& ctx, const Params&) -> PlannerSource {
    double boundary = 0.0;
    for (const BoundaryEdge& b : ctx.environment.boundary())
      boundary += distance(b.a, b.b);
    TangentBugParams p = TangentBugParams::for_environment(ctx.environment.diameter(), boundary);
    // A decrease smaller than the sensor's noise is no progress: three standard deviations.
    p.progress = std::max(p.progress, 3.0 * ctx.sensor.spread());
    p.noise_margin = 3.0 * ctx.sensor.spread();
    p.drift = ctx.sensor.position_sigma;
    return [p] { return std::make_unique<TangentBug>(p); };
  };
  e.contract.complete = true;
  e.contract.keeps_direction = true;
  // An empirical envelope, not a theorem (Kamon et al. prove termination, not a length
  // bound), evaluated with the map the planner never sees (which ring each recorded point
  // lies on): L* + for each boundary-following episode the followed ring's perimeter and
  // the way from where the episode began to that ring + the perimeter of each ring only
  // steered round + every leave segment (+ half the enclosing ring's perimeter for a goal
  // outside Ω: the way to the projection); range noise makes local minima and leave points
  // where there are none, so with noise 1.5 times that (docs/tangent_bug.md).
  e.contract.path_bound = [](const PathBoundCase& c) {
    const auto& bug = dynamic_cast<const TangentBug&>(c.planner);
    const Environment& env = c.environment;
    const auto ring_of = [&](Vec2 p) {
      std::uint32_t ring = 0;
      double near = kInf;
      for (const BoundaryEdge& b : env.boundary()) {
        const double d = distance(project_to_segment(p, b.a, b.b).point, p);
        if (d < near) near = d, ring = b.ring;
      }
      return ring;
    };
    const auto perimeter = [&](std::uint32_t ring) {
      const std::vector<Vec2>& r = env.rings()[ring];
      double sum = 0.0;
      for (std::size_t i = 0; i < r.size(); ++i)
        sum += distance(r[i], r[(i + 1) % r.size()]);
      return sum;
    };
    double bound = c.shortest + bug.leave_length();
    std::vector<std::uint32_t> followed;
    for (const TangentBug::Episode& ep : bug.episodes()) {
      followed.push_back(ring_of(ep.boundary));
      bound += perimeter(followed.back()) + distance(ep.start, ep.boundary);
    }
    std::vector<std::uint32_t> steered;
    for (Vec2 p : bug.engaged())
      steered.push_back(ring_of(p));
    std::sort(steered.begin(), steered.end());
    steered.erase(std::unique(steered.begin(), steered.end()), steered.end());
    for (std::uint32_t ring : steered) {
      if (std::find(followed.begin(), followed.end(), ring) == followed.end())
        bound += perimeter(ring);
    }
    if (!c.reachable && !followed.empty()) bound += 0.5 * perimeter(followed.back());
    return c.noise_sigma > 0.0 ? 1.5 * bound : bound;
  };
  return e;
}

}  // namespace covsim
