#include "planners/tangent_bug.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/environment.hpp"
#include "planners/local_tangent_graph.hpp"

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

std::string_view to_string(TangentBug::Mode m) {
  switch (m) {
    case TangentBug::Mode::motion_to_goal:
      return "motion_to_goal";
    case TangentBug::Mode::approach:
      return "approach";
    case TangentBug::Mode::follow:
      return "follow";
    case TangentBug::Mode::leave:
      return "leave";
    case TangentBug::Mode::to_projection:
      return "to_projection";
    case TangentBug::Mode::to_closest:
      return "to_closest";
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
  idle_steps_ = 0;
  episodes_.clear();
  engaged_.clear();
  loops_ = recoveries_ = 0;
  leave_length_ = 0.0;
}

void TangentBug::move_goal(Vec2 goal) {
  if (mode_ == Mode::done || mode_ == Mode::to_projection) return set_goal(goal);
  const double shift = distance(goal, goal_);
  goal_ = goal;
  h_prev_ += shift;
  bound_ += shift;
  d_followed_ += shift;
  idle_steps_ = 0;
  // A leave stays committed to its point (turned into motion toward the moved goal, it can
  // meet the wall it left and walk round it again); an approach heads for the goal as it is
  // now, so that the wall it meets is followed the way the robot was going.
  if (mode_ == Mode::approach) heading_ = goal_;
}

PlanStep TangentBug::finish(Vec2 at, PlanStatus s) {
  mode_ = Mode::done;
  status_ = s;
  return PlanStep{at, s};
}

PlanStep TangentBug::move_toward(Vec2 x, Vec2 p, double max_step) {
  const double d = distance(x, p);
  return PlanStep{d <= max_step ? p : x + (max_step / d) * (p - x), PlanStatus::moving};
}

void TangentBug::resume_motion_to_goal() {
  mode_ = Mode::motion_to_goal;
  h_prev_ = kInf;
}

PlanStep TangentBug::step(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (mode_ == Mode::done) return PlanStep{x, status_};
  // Bookkeeping from where the robot actually is (the world may have stopped a motion).
  if (last_position_) {
    const double moved = distance(*last_position_, x);
    path_ += moved;
    idle_steps_ = moved > p_.tolerance ? 0 : idle_steps_ + 1;
    if (moved > p_.tolerance) motion_ = (x - *last_position_) / moved;
  }
  last_position_ = x;
  if (path_ > p_.path_budget || idle_steps_ > kMaxIdleSteps) return finish(x, PlanStatus::stalled);
  for (const ContactEdge& c : r.contacts)
    memory_.remember(c);
  if (distance(goal_, x) <= p_.tolerance) return finish(goal_, PlanStatus::reached);
  // A mode change decides again at once; a handful always settles on a motion.
  for (int hop = 0; hop < 8; ++hop) {
    Decision d;
    switch (mode_) {
      case Mode::motion_to_goal:
        d = motion_to_goal(r, max_step);
        break;
      case Mode::approach:
        d = approach(r, max_step);
        break;
      case Mode::follow:
        d = follow(r, max_step);
        break;
      case Mode::leave:
        d = leave(r, max_step);
        break;
      case Mode::to_projection:
      case Mode::to_closest:
        d = walk_on(r, max_step);
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
  // Touching an obstacle walked round before that encloses the goal: project at once.
  for (const ContactEdge& c : r.contacts) {
    if (memory_.complete(c.ring) && memory_.encloses(c.ring, goal_))
      return walk_to(r, c.ring, Mode::to_projection);
  }
  const std::vector<TangentNode> nodes =
      tangent_nodes(r, goal_, bound_ - p_.progress, p_.tolerance);
  const TangentNode* best = nullptr;
  for (const TangentNode& n : nodes) {
    if (best == nullptr || n.heuristic < best->heuristic) best = &n;
  }
  // The heuristic distance must not increase: moving toward a node lowers it by the step,
  // and a better node lowers it more.
  if (best != nullptr && best->heuristic <= h_prev_ + p_.tolerance) {
    h_prev_ = best->heuristic;
    heading_ = best->point;
    if (!best->is_goal) engage(best->ring);
    return move_toward(x, best->point, max_step);
  }
  // A local minimum: follow the obstacle in the way, touching it first.
  const FreeRay f = free_ray(r, unit(goal_ - x), p_.tolerance);
  if (f.distance == 0.0) return begin_following(r, *f.blocker);
  mode_ = Mode::approach;
  heading_ = goal_;
  return std::nullopt;
}

TangentBug::Decision TangentBug::approach(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  // Straight toward the goal until a wall the robot touches faces it: up to the sensed wall,
  // and past it by the noise margin, so that a sensed point that noise put short of the wall
  // does not hold the robot up (the world stops a motion at the wall).
  const FreeRay f = free_ray(r, unit(goal_ - x), p_.tolerance);
  if (f.distance == 0.0) return begin_following(r, *f.blocker);
  return move_toward(x, goal_, std::min(max_step, f.distance + p_.noise_margin));
}

TangentBug::Decision TangentBug::begin_following(const SensorReading& r, std::uint32_t ring) {
  const Vec2 x = r.position;
  if (memory_.complete(ring) && memory_.encloses(ring, goal_))
    return walk_to(r, ring, Mode::to_projection);
  // The direction that continues the motion (Kamon et al.): toward the point last headed
  // for while it lies ahead; standing on it, the direction of the last step that moved;
  // only a robot that has never moved takes the goal's. Between two equally good ones, the
  // one whose edge ends nearer the goal.
  const bool ahead = heading_ && distance(*heading_, x) > p_.tolerance;
  const Vec2 ref = ahead ? unit(*heading_ - x) : motion_ ? *motion_ : unit(goal_ - x);
  int dir = 0;
  double best_score = -kInf, best_end = kInf;
  for (int d : {1, -1}) {
    const auto e = walking_edge(r, d, p_.tolerance);
    if (!e) continue;
    const Vec2 end = d > 0 ? e->b : e->a;
    const double score = dot(unit(end - x), ref), to_goal = distance(end, goal_);
    if (score > best_score + 1e-9 ||
        (std::fabs(score - best_score) <= 1e-9 && to_goal < best_end)) {
      best_score = score;
      best_end = to_goal;
      dir = d;
    }
  }
  if (dir == 0) return finish(x, PlanStatus::stalled);  // touching nothing to walk along
  mode_ = Mode::follow;
  ring_ = ring;
  dir_ = dir;
  start_ = x;
  walked_ = 0.0;
  d_followed_ = distance(x, goal_);
  episodes_.push_back(ring);
  engage(ring);
  return std::nullopt;
}

void TangentBug::engage(std::uint32_t ring) {
  const auto it = std::lower_bound(engaged_.begin(), engaged_.end(), ring);
  if (it == engaged_.end() || *it != ring) engaged_.insert(it, ring);
}

TangentBug::Decision TangentBug::follow(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  // d_followed: the followed obstacle as sensed now, except the point under the robot (so
  // that a contact sensor can still leave where it stands).
  for (std::size_t k = 0; k < r.visible.pieces.size(); ++k) {
    if (r.piece_rings[k] != ring_) continue;
    const Vec2 q = project_to_segment(goal_, r.visible.pieces[k].a, r.visible.pieces[k].b).point;
    if (distance(q, x) > p_.tolerance)
      d_followed_ = std::min(d_followed_, distance(q, goal_) + p_.noise_margin);
  }
  const ReachPoint reach = reach_point(r, goal_, ring_, p_.tolerance);
  if (reach.distance < d_followed_ - p_.progress) {
    bound_ = d_followed_;  // what every later node and leave must beat
    leave_to_ = reach.point;
    leave_length_ += distance(x, leave_to_);
    mode_ = Mode::leave;
    return std::nullopt;
  }
  d_followed_ = std::min(d_followed_, distance(x, goal_));
  if (walked_ > p_.tolerance && distance(x, start_) <= p_.tolerance) return loop_closed(r);
  return walk(r, max_step, start_);
}

TangentBug::Decision TangentBug::leave(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  const double d = distance(x, leave_to_);
  // Arrived, or a wall the robot touches stands in the way (possible only with noise).
  if (d <= p_.tolerance || free_ray(r, (leave_to_ - x) / d, p_.tolerance).distance == 0.0) {
    resume_motion_to_goal();
    return std::nullopt;
  }
  heading_ = leave_to_;
  return move_toward(x, leave_to_, max_step);
}

TangentBug::Decision TangentBug::loop_closed(const SensorReading& r) {
  memory_.close(ring_);
  ++loops_;
  if (memory_.encloses(ring_, goal_)) return walk_to(r, ring_, Mode::to_projection);
  ++recoveries_;
  return walk_to(r, ring_, Mode::to_closest);
}

TangentBug::Decision TangentBug::walk_to(const SensorReading& r, std::uint32_t ring, Mode mode) {
  const Vec2 x = r.position;
  ring_ = ring;
  mode_ = mode;
  target_ = memory_.closest(ring, goal_);
  // The shorter way round.
  const auto ef = walking_edge(r, 1, p_.tolerance), eb = walking_edge(r, -1, p_.tolerance);
  const double af = ef ? memory_.arc(ring, {x, ef->index}, target_, 1) : kInf;
  const double ab = eb ? memory_.arc(ring, {x, eb->index}, target_, -1) : kInf;
  dir_ = af <= ab ? 1 : -1;
  return std::nullopt;
}

TangentBug::Decision TangentBug::walk_on(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (distance(x, target_.point) <= p_.tolerance) {
    if (mode_ == Mode::to_projection) return finish(target_.point, PlanStatus::projected);
    // The way toward the goal is free here: motion to goal again, no bound from before.
    resume_motion_to_goal();
    bound_ = kInf;
    return std::nullopt;
  }
  return walk(r, max_step, target_.point);
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
  e.description =
      "TangentBug (Kamon et al. 1998) with target projection; range sensor of any range";
  e.make = [](const PlannerContext& ctx, const Params&) -> PlannerSource {
    double boundary = 0.0;
    for (const BoundaryEdge& b : ctx.environment.boundary())
      boundary += distance(b.a, b.b);
    TangentBugParams p = TangentBugParams::for_environment(ctx.environment.diameter(), boundary);
    // A decrease smaller than the sensor's noise is no progress: three standard deviations.
    p.progress = std::max(p.progress, 3.0 * ctx.sensor.noise_sigma);
    p.noise_margin = 3.0 * ctx.sensor.noise_sigma;
    return [p] { return std::make_unique<TangentBug>(p); };
  };
  e.contract.complete = true;
  // An empirical envelope, not a theorem (Kamon et al. prove termination, not a length
  // bound): L* + the perimeter of the ring followed in each boundary-following episode + that
  // of each ring only steered round + every leave segment (a leave heads for the visible
  // point nearest the goal, however far off the shortest path) (+ half the enclosing ring's
  // perimeter for a goal outside Ω: the walk to the projection); range noise makes local
  // minima and leave points where there are none, so with noise 1.5 times that
  // (docs/tangent_bug.md).
  e.contract.path_bound = [](const PathBoundCase& c) {
    const auto& bug = dynamic_cast<const TangentBug&>(c.planner);
    const auto perimeter = [&](std::uint32_t ring) {
      const std::vector<Vec2>& r = c.environment.rings()[ring];
      double sum = 0.0;
      for (std::size_t i = 0; i < r.size(); ++i)
        sum += distance(r[i], r[(i + 1) % r.size()]);
      return sum;
    };
    double bound = c.shortest + bug.leave_length();
    const auto& episodes = bug.episodes();
    for (std::uint32_t ring : episodes)
      bound += perimeter(ring);
    for (std::uint32_t ring : bug.engaged()) {
      if (std::find(episodes.begin(), episodes.end(), ring) == episodes.end())
        bound += perimeter(ring);
    }
    if (!c.reachable && !episodes.empty()) bound += 0.5 * perimeter(episodes.back());
    return c.noise_sigma > 0.0 ? 1.5 * bound : bound;
  };
  return e;
}

}  // namespace covsim
