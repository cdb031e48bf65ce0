#include "geometry/ring_validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "geometry/convex_polygon.hpp"
#include "geometry/geometry_error.hpp"
#include "geometry/predicates.hpp"

namespace covsim {

namespace {
Box box_of(Vec2 a, Vec2 b) {
  Box box;
  box.add(a);
  box.add(b);
  return box;
}
Box box_of(const std::vector<Vec2>& ring) {
  Box box;
  for (Vec2 p : ring)
    box.add(p);
  return box;
}
// The first pair of intersecting edges between rings a and b (closed segments).
std::optional<std::pair<std::size_t, std::size_t>> rings_meet(const std::vector<Vec2>& a,
                                                              const std::vector<Vec2>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 p = a[i], q = a[(i + 1) % a.size()];
    const Box bi = box_of(p, q);
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2 r = b[j], s = b[(j + 1) % b.size()];
      if (bi.overlaps(box_of(r, s)) && segments_intersect(p, q, r, s)) return std::make_pair(i, j);
    }
  }
  return std::nullopt;
}
}  // namespace

std::string ring_name(std::size_t ring) {
  return ring == 0 ? std::string("outer ring") : fmt::format("hole {}", ring - 1);
}

std::vector<Vec2> normalize_ring(std::vector<Vec2> ring, std::size_t ring_index,
                                 bool counter_clockwise) {
  const std::string name = ring_name(ring_index);
  const int at = static_cast<int>(ring_index);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (!is_finite(ring[i]))
      throw GeometryError(fmt::format("{}: vertex {} has a non-finite coordinate", name, i), at);
  }
  std::vector<Vec2> r;
  for (Vec2 p : ring) {
    if (r.empty() || !(p == r.back())) r.push_back(p);
  }
  while (r.size() > 1 && r.front() == r.back())
    r.pop_back();
  if (r.size() < 3) {
    throw GeometryError(
        fmt::format("{}: needs at least 3 distinct vertices, has {}", name, r.size()), at);
  }
  bool collinear = true;
  for (std::size_t i = 2; i < r.size() && collinear; ++i)
    collinear = orientation(r[0], r[1], r[i]) == 0;
  if (collinear)
    throw GeometryError(fmt::format("{}: has zero area (all vertices on one line)", name), at);

  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = r[i], b = r[(i + 1) % n];
    // Adjacent edges may only share their common vertex: a fold-back overlaps.
    const Vec2 c = r[(i + 2) % n];
    if (orientation(a, b, c) == 0 && dot(a - b, c - b) > 0.0) {
      throw GeometryError(fmt::format("{}: edges {} and {} fold back onto each other at vertex {}",
                                      name, i, (i + 1) % n, (i + 1) % n),
                          at);
    }
    const Box bi = box_of(a, b);
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing vertex
      const Vec2 p = r[j], q = r[(j + 1) % n];
      if (bi.overlaps(box_of(p, q)) && segments_intersect(a, b, p, q)) {
        throw GeometryError(fmt::format("{}: is self-intersecting: edge {} (vertex {} to {}) meets "
                                        "edge {} (vertex {} to {})",
                                        name, i, i, (i + 1) % n, j, j, (j + 1) % n),
                            at);
      }
    }
  }
  if ((signed_area(r) > 0.0) != counter_clockwise) std::reverse(r.begin(), r.end());
  return r;
}

bool inside_ring(const std::vector<Vec2>& ring, Vec2 p) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = ring[i], b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

void check_hole_placement(const std::vector<std::vector<Vec2>>& rings) {
  std::vector<Box> boxes;
  for (const auto& r : rings)
    boxes.push_back(box_of(r));
  for (std::size_t h = 1; h < rings.size(); ++h) {
    if (auto meet = rings_meet(rings[h], rings[0])) {
      throw GeometryError(
          fmt::format("{}: is not strictly inside the outer ring: its edge {} touches or crosses "
                      "edge {} of the outer ring",
                      ring_name(h), meet->first, meet->second),
          static_cast<int>(h));
    }
    if (!inside_ring(rings[0], rings[h][0])) {
      throw GeometryError(
          fmt::format("{}: is not inside the outer ring (vertex 0 at ({}, {}) is outside)",
                      ring_name(h), rings[h][0].x, rings[h][0].y),
          static_cast<int>(h));
    }
  }
  for (std::size_t a = 1; a < rings.size(); ++a) {
    for (std::size_t b = a + 1; b < rings.size(); ++b) {
      if (!boxes[a].overlaps(boxes[b])) continue;
      if (auto meet = rings_meet(rings[a], rings[b])) {
        throw GeometryError(
            fmt::format(
                "{} and {} overlap or touch: edge {} of the first meets edge {} of the second",
                ring_name(a), ring_name(b), meet->first, meet->second),
            static_cast<int>(b));
      }
      if (inside_ring(rings[a], rings[b][0]) || inside_ring(rings[b], rings[a][0])) {
        throw GeometryError(
            fmt::format("{} and {} overlap: one lies inside the other", ring_name(a), ring_name(b)),
            static_cast<int>(b));
      }
    }
  }
}

}  // namespace covsim
