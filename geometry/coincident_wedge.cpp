#include "geometry/coincident_wedge.hpp"

#include <cmath>
#include <numbers>

namespace covsim {

namespace {
// The direction at angle 2πk/m; exact on the axes.
Vec2 direction(std::size_t k, std::size_t m) {
  k %= m;
  if ((4 * k) % m == 0) {
    switch (4 * k / m) {
      case 0:
        return {1, 0};
      case 1:
        return {0, 1};
      case 2:
        return {-1, 0};
      default:
        return {0, -1};
    }
  }
  const double a = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(m);
  return {std::cos(a), std::sin(a)};
}
}  // namespace

void clip_to_wedge(ConvexPolygon& cell, Vec2 g, std::size_t rank, std::size_t count) {
  const Vec2 a = direction(rank, count), b = direction(rank + 1, count);
  // Counter-clockwise of a: cross(a, x - g) >= 0; clockwise of b: cross(b, x - g) <= 0. For
  // two generators both describe the same half-plane.
  ConvexPolygon tmp;
  clip(cell, HalfPlane{-perp(a), dot(-perp(a), g)}, tmp);
  clip(tmp, HalfPlane{perp(b), dot(perp(b), g)}, cell);
}

}  // namespace covsim
