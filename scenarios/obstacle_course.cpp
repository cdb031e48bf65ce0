#include "scenarios/obstacle_course.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/random_stream.hpp"
#include "geometry/ring_validation.hpp"

namespace covsim {

std::string_view to_string(ObstacleShape s) {
  switch (s) {
    case ObstacleShape::box:
      return "box";
    case ObstacleShape::thin_wall:
      return "thin_wall";
    case ObstacleShape::t_wall:
      return "t_wall";
    case ObstacleShape::l_wall:
      return "l_wall";
    case ObstacleShape::e_wall:
      return "e_wall";
    case ObstacleShape::comb:
      return "comb";
    case ObstacleShape::cup:
      return "cup";
  }
  return "unknown";
}

namespace {

using Ring = std::vector<Vec2>;

struct Outline {
  Ring ring;
  double slot = INFINITY;  // the width of the narrowest slot between its arms
};

// Outlines in local coordinates: arms of thickness t.
Outline shape_outline(ObstacleShape s, RandomStream& rng) {
  const double t = rng.uniform(0.03, 0.2);
  const double a = rng.uniform(0.8, 3.0), b = rng.uniform(0.8, 3.0);
  switch (s) {
    case ObstacleShape::box: {
      const double w = rng.uniform(0.2, 1.6), h = rng.uniform(0.2, 1.6);
      return {{{0, 0}, {w, 0}, {w, h}, {0, h}}};
    }
    case ObstacleShape::thin_wall:
      return {{{0, 0}, {a, 0}, {a, t}, {0, t}}};
    case ObstacleShape::t_wall:
      return {{{-a / 2, 0},
               {a / 2, 0},
               {a / 2, t},
               {t / 2, t},
               {t / 2, b},
               {-t / 2, b},
               {-t / 2, t},
               {-a / 2, t}}};
    case ObstacleShape::l_wall:
      return {{{0, 0}, {a, 0}, {a, t}, {t, t}, {t, b}, {0, b}}};
    case ObstacleShape::e_wall: {
      const double h = std::max(b, 5 * t), m = (h - t) / 2;
      return {{{0, 0},
               {a, 0},
               {a, t},
               {t, t},
               {t, m},
               {a, m},
               {a, m + t},
               {t, m + t},
               {t, h - t},
               {a, h - t},
               {a, h},
               {0, h}},
              m - t};
    }
    case ObstacleShape::comb: {
      const auto k = static_cast<int>(3 + rng.below(3));  // teeth
      const double w = std::max(a, 2.0 * k * t);
      Ring r{{0, 0}, {w, 0}};
      for (int i = k - 1; i >= 0; --i) {
        const double x = i * (w - t) / (k - 1);
        if (i == k - 1) {
          r.insert(r.end(), {{x + t, b}, {x, b}, {x, t}});
        } else {
          r.insert(r.end(), {{x + t, t}, {x + t, b}, {x, b}});
          if (i > 0) r.push_back({x, t});
        }
      }
      return {r, (w - t) / (k - 1) - t};
    }
    case ObstacleShape::cup: {
      const double w = std::max(a, 4 * t), h = std::max(b, 2 * t);
      return {{{0, 0}, {w, 0}, {w, h}, {w - t, h}, {w - t, t}, {t, t}, {t, h}, {0, h}}, w - 2 * t};
    }
  }
  return {};
}

double ring_distance(const Ring& p, const Ring& q) {
  double d = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = 0; j < q.size(); ++j) {
      d = std::min(d, segment_distance(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()]));
    }
  }
  return d;
}

// Notches narrow the narrowest passage to their width.
Ring outer_ring(const ObstacleCourseSpec& spec, RandomStream& rng, double& narrowest) {
  const double w = spec.width, h = spec.height;
  Ring r{{0, 0}};
  const auto notch = [&](bool top) {
    const double nw = rng.uniform(0.3, 0.12 * w), depth = rng.uniform(0.1, 0.25) * h;
    const double x0 = rng.uniform(0.15 * w, 0.85 * w - nw);
    narrowest = std::min(narrowest, nw);
    if (top) {
      r.insert(r.end(), {{x0 + nw, h}, {x0 + nw, h - depth}, {x0, h - depth}, {x0, h}});
    } else {
      r.insert(r.end(), {{x0, 0}, {x0, depth}, {x0 + nw, depth}, {x0 + nw, 0}});
    }
  };
  const std::uint32_t notches = spec.notches == 0 ? 0 : rng.below(spec.notches + 1);
  if (notches >= 1) notch(false);
  r.insert(r.end(), {{w, 0}, {w, h}});
  if (notches >= 2) notch(true);
  r.push_back({0, h});
  return r;
}

}  // namespace

ObstacleCourse obstacle_course(std::uint64_t seed, const ObstacleCourseSpec& spec) {
  if (!(spec.width >= 4.0 && spec.height >= 4.0 && spec.width <= 1e4 && spec.height <= 1e4))
    throw std::invalid_argument("obstacle course: width and height must lie in [4, 1e4] m");
  if (!(spec.clearance > 0.0 && spec.clearance < 0.25 * std::min(spec.width, spec.height)))
    throw std::invalid_argument("obstacle course: clearance must be positive and small");
  if (spec.obstacles > 200) throw std::invalid_argument("obstacle course: at most 200 obstacles");
  RandomStream rng(seed, 0, "obstacle-course");
  ObstacleCourse c;
  c.narrowest = spec.clearance;
  c.outer = outer_ring(spec, rng, c.narrowest);
  constexpr ObstacleShape kShapes[] = {
      ObstacleShape::box,    ObstacleShape::thin_wall, ObstacleShape::t_wall, ObstacleShape::l_wall,
      ObstacleShape::e_wall, ObstacleShape::comb,      ObstacleShape::cup};
  for (int attempt = 0;
       attempt < 60 * static_cast<int>(spec.obstacles) && c.holes.size() < spec.obstacles;
       ++attempt) {
    const ObstacleShape shape = kShapes[rng.below(std::size(kShapes))];
    const Outline local = shape_outline(shape, rng);
    const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const Vec2 at{rng.uniform(0.0, spec.width), rng.uniform(0.0, spec.height)};
    const double cs = std::cos(angle), sn = std::sin(angle);
    Ring hole;
    for (Vec2 p : local.ring)
      hole.push_back(at + Vec2{cs * p.x - sn * p.y, sn * p.x + cs * p.y});
    bool fits = ring_distance(hole, c.outer) >= spec.clearance;
    for (Vec2 p : hole)
      fits = fits && inside_ring(c.outer, p);
    for (const Ring& other : c.holes) {
      fits = fits && ring_distance(hole, other) >= spec.clearance && !inside_ring(other, hole[0]) &&
             !inside_ring(hole, other[0]);
    }
    if (!fits) continue;
    c.holes.push_back(std::move(hole));
    c.shapes.push_back(shape);
    c.narrowest = std::min(c.narrowest, local.slot);
  }
  return c;
}

CombCourse comb_course(std::uint64_t seed) {
  RandomStream rng(seed, 0, "comb-course");
  const auto k = static_cast<int>(5 + rng.below(5));  // teeth
  const double gap = rng.uniform(0.3, 0.6), t = rng.uniform(0.05, 0.15);
  const double depth = rng.uniform(1.0, 1.5), bar = rng.uniform(0.1, 0.2);
  const double margin = rng.uniform(0.6, 1.2), w = k * t + (k - 1) * gap;
  const double y0 = 1.5, top = y0 + depth + bar;  // the tips' line and the bar's back
  CombCourse c;
  c.depth = depth;
  c.course.outer = {{0, 0}, {w + 2 * margin, 0}, {w + 2 * margin, top + 1.5}, {0, top + 1.5}};
  // Counter-clockwise: along the tips and gaps, up the last tooth, back along the bar.
  Ring comb;
  for (int i = 0; i < k; ++i) {
    const double x = margin + i * (t + gap);
    if (i > 0) comb.push_back({x, y0 + depth});
    comb.insert(comb.end(), {{x, y0}, {x + t, y0}});
    if (i + 1 < k) comb.push_back({x + t, y0 + depth});
  }
  comb.insert(comb.end(), {{margin + w, top}, {margin, top}});
  c.course.holes.push_back(std::move(comb));
  c.course.shapes.push_back(ObstacleShape::comb);
  c.course.narrowest = std::min(gap, margin);
  c.below.add({margin, y0 - 1.2});
  c.below.add({margin + w, y0 - 0.2});
  c.above.add({margin, top + 0.2});
  c.above.add({margin + w, top + 1.2});
  return c;
}

}  // namespace covsim
