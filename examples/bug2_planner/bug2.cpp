#include "bug2.hpp"

#include <cmath>

#include "geometry/environment.hpp"
#include "planners/local_tangent_graph.hpp"

namespace example {

using namespace covsim;

namespace {
Vec2 unit(Vec2 v) {
  const double n = norm(v);
  return n > 0.0 ? v / n : Vec2{0, 0};
}
}  // namespace

void Bug2::set_goal(Vec2 goal) {
  goal_ = goal;
  line_start_.reset();
  mode_ = Mode::line;
  status_ = PlanStatus::moving;
}

PlanStep Bug2::finish(Vec2 at, PlanStatus s) {
  mode_ = Mode::done;
  status_ = s;
  return {at, s};
}

PlanStep Bug2::step(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (mode_ == Mode::done) return {x, status_};
  if (!line_start_) line_start_ = x;
  const double dg = distance(x, goal_);
  if (dg <= tolerance_) return finish(goal_, PlanStatus::reached);
  const Vec2 u = (goal_ - x) / dg;
  if (mode_ == Mode::line) {
    const FreeRay f = free_ray(r, u, tolerance_);
    if (f.distance > 0.0) return {dg <= max_step ? goal_ : x + max_step * u, PlanStatus::moving};
    // A wall faces the goal: follow it, keeping it on the right.
    mode_ = Mode::follow;
    hit_ = x;
    walked_ = 0.0;
    walked_points_.assign(1, x);
  }
  if (mode_ == Mode::follow) {
    // Back on the m-line, closer than the hit point, with the way free: leave.
    const Vec2 a = *line_start_;
    const bool on_line = std::fabs(cross(goal_ - a, x - a)) <= tolerance_ * norm(goal_ - a);
    if (walked_ > tolerance_ && on_line && dg < distance(hit_, goal_) - tolerance_ &&
        free_ray(r, u, tolerance_).distance > 0.0) {
      mode_ = Mode::line;
      return step(r, max_step);
    }
    // It stops at every vertex, so its positions along the wall are the obstacle.
    if (distance(x, walked_points_.back()) > tolerance_) walked_points_.push_back(x);
    if (walked_ > tolerance_ && distance(x, hit_) <= tolerance_) {
      obstacle_.emplace(walked_points_, 1, tolerance_);
      if (!obstacle_->encloses(goal_)) return finish(x, PlanStatus::stalled);
      mode_ = Mode::to_projection;
      target_ = obstacle_->closest(goal_);
    } else {
      return walk(r, max_step, hit_);
    }
  }
  if (distance(x, target_.point) <= tolerance_) return finish(target_.point, PlanStatus::projected);
  return walk(r, max_step, target_.point);
}

PlanStep Bug2::walk(const SensorReading& r, double max_step, std::optional<Vec2> stop) {
  const Vec2 x = r.position;
  const auto e = walking_edge(r, 1, tolerance_);
  if (!e) return finish(x, PlanStatus::stalled);
  Vec2 target = e->b;
  double dt = distance(e->b, x);
  const auto consider = [&](Vec2 w) {
    const double dw = distance(w, x);
    if (dw <= tolerance_ || dw >= dt) return;
    if (distance(project_to_segment(w, x, e->b).point, w) > tolerance_) return;
    target = w;
    dt = dw;
  };
  if (stop) consider(*stop);
  // Where this edge crosses the m-line, so that the leave test sees that point.
  const Vec2 a = *line_start_, d = goal_ - a, s = e->b - x;
  const double denom = cross(s, d);
  if (std::fabs(denom) > 1e-12 * norm(s) * norm(d)) {
    const double t = cross(a - x, d) / denom;
    if (t > 0.0 && t < 1.0) consider(x + t * s);
  }
  const Vec2 next = dt <= max_step ? target : x + max_step * unit(target - x);
  walked_ += distance(x, next);
  return {next, PlanStatus::moving};
}

PlannerEntry bug2_entry() {
  PlannerEntry e;
  e.name = "bug2";
  e.description = "Bug2 with a contact sensor (an example planner built outside covsim)";
  e.make = [](const PlannerContext& ctx, const Params&) -> PlannerSource {
    const double tolerance = ctx.environment.tolerance();
    return [tolerance] { return std::make_unique<Bug2>(tolerance); };
  };
  return e;
}

}  // namespace example
