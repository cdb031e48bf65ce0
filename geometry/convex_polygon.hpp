#pragma once
// Convex polygons: clipping by half-planes and exact area moments. Cells of a Voronoi
// partition and the free-space triangles are both convex, so every region covsim
// integrates over is a union of such pieces.
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

// Counter-clockwise vertices of a convex polygon (possibly empty).
using ConvexPolygon = std::vector<Vec2>;

// The half-plane { x : dot(normal, x) <= offset }.
struct HalfPlane {
  Vec2 normal;
  double offset;
  double signed_distance(Vec2 p) const { return dot(normal, p) - offset; }
};

// The points at least as close to a as to b: the Voronoi half-plane of a against b.
inline HalfPlane bisector_half_plane(Vec2 a, Vec2 b) {
  const Vec2 n = b - a;
  return {n, dot(n, 0.5 * (a + b))};
}

// Clips `in` by the half-plane into `out` (Sutherland-Hodgman; `out` is overwritten).
void clip(const ConvexPolygon& in, const HalfPlane& h, ConvexPolygon& out);

// Area moments of a polygon relative to a reference point r, for density 1:
// mass = area, first = integral of (x - r), second = integral of |x - r|^2.
struct Moments {
  double mass = 0.0;
  Vec2 first;
  double second = 0.0;
  Moments& operator+=(const Moments& o) {
    mass += o.mass;
    first += o.first;
    second += o.second;
    return *this;
  }
  Moments scaled(double s) const { return {s * mass, s * first, s * second}; }
};
// Exact (up to rounding) for any simple polygon given counter-clockwise.
Moments polygon_moments(const std::vector<Vec2>& poly, Vec2 r);
double signed_area(const std::vector<Vec2>& poly);

}  // namespace covsim
