#include "geometry/velocity_program.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace covsim {

namespace {

constexpr double kParallel = 1e-12;

// The best point of plane k's boundary line inside the disk and the planes before k: nearest
// to `target`, or furthest along it when `along` (then target is a direction). False when the
// line has no such point.
bool best_on_line(const std::vector<VelocityConstraint>& planes, std::size_t k, double radius, Vec2 target,
                  bool along, Vec2& out) {
  const VelocityConstraint& h = planes[k];
  // The line p + t d meets the disk |v| <= radius for t in [lo, hi].
  const double b = dot(h.point, h.direction);
  const double disc = b * b + radius * radius - norm2(h.point);
  if (disc < 0.0) return false;
  const double root = std::sqrt(disc);
  double lo = -b - root, hi = -b + root;
  for (std::size_t j = 0; j < k; ++j) {
    const VelocityConstraint& g = planes[j];
    const double denom = cross(g.direction, h.direction);
    const double num = cross(g.direction, h.point - g.point);
    if (std::fabs(denom) <= kParallel) {
      if (num < 0.0) return false;  // parallel and wholly outside plane j
      continue;
    }
    const double t = -num / denom;
    if (denom > 0.0)
      lo = std::max(lo, t);
    else
      hi = std::min(hi, t);
    if (lo > hi) return false;
  }
  double t;
  if (along)
    t = dot(target, h.direction) > 0.0 ? hi : lo;
  else
    t = std::clamp(dot(h.direction, target - h.point), lo, hi);
  out = h.point + t * h.direction;
  return true;
}

// The planes' first k constraints in the disk: returns the count satisfied in order (all of
// them when it equals planes.size()), `out` the optimum of those.
std::size_t solve(const std::vector<VelocityConstraint>& planes, double radius, Vec2 target, bool along,
                  Vec2& out) {
  if (along) {
    out = radius * target;
  } else if (norm2(target) > radius * radius) {
    out = (radius / norm(target)) * target;
  } else {
    out = target;
  }
  for (std::size_t k = 0; k < planes.size(); ++k) {
    if (cross(planes[k].direction, out - planes[k].point) >= 0.0) continue;
    const Vec2 before = out;
    if (!best_on_line(planes, k, radius, target, along, out)) {
      out = before;
      return k;
    }
  }
  return planes.size();
}

}  // namespace

VelocityChoice closest_permitted_velocity(const std::vector<VelocityConstraint>& planes, double max_speed,
                                          Vec2 preferred) {
  VelocityChoice c;
  const std::size_t done = solve(planes, max_speed, preferred, false, c.velocity);
  if (done == planes.size()) return c;
  // Infeasible: minimize the largest violation. Each plane from the first that failed on,
  // violated by more than the worst so far, is met by moving into it while keeping the
  // earlier planes violated no more than it is: the bisectors of it and each of them.
  c.feasible = false;
  double worst = 0.0;
  for (std::size_t k = done; k < planes.size(); ++k) {
    const VelocityConstraint& h = planes[k];
    if (cross(h.direction, h.point - c.velocity) <= worst) continue;
    std::vector<VelocityConstraint> bisectors;
    for (std::size_t j = 0; j < k; ++j) {
      const VelocityConstraint& g = planes[j];
      VelocityConstraint b;
      const double denom = cross(h.direction, g.direction);
      if (std::fabs(denom) <= kParallel) {
        if (dot(h.direction, g.direction) > 0.0) continue;  // the same side: nothing new
        b.point = 0.5 * (h.point + g.point);
      } else {
        b.point = h.point + (cross(g.direction, h.point - g.point) / denom) * h.direction;
      }
      const Vec2 d = g.direction - h.direction;
      b.direction = d / norm(d);
      bisectors.push_back(b);
    }
    const Vec2 before = c.velocity;
    // Furthest into plane k: along its inward normal.
    if (solve(bisectors, max_speed, Vec2{-h.direction.y, h.direction.x}, true, c.velocity) <
        bisectors.size())
      c.velocity = before;  // rounding only: the bisectors always admit a point
    worst = cross(h.direction, h.point - c.velocity);
  }
  return c;
}

}  // namespace covsim
