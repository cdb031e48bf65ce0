#pragma once
// Exact geometric predicates (CGAL's filtered predicates, in one translation unit), for
// validation where a wrong answer would accept a bad polygon, and for the combinatorial
// decisions of visibility, where a wrong sign hides a wall.
#include <cmath>

#include "core/vec2.hpp"

namespace covsim {

int orientation_exact(Vec2 a, Vec2 b, Vec2 c);

// +1 if a, b, c turn counter-clockwise, -1 if clockwise, 0 if collinear; exactly. The
// determinant in doubles decides when it clears its rounding error bound (Shewchuk's
// orient2d filter), which is almost always; CGAL decides the rest.
inline int orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double left = (a.x - c.x) * (b.y - c.y), right = (a.y - c.y) * (b.x - c.x);
  const double det = left - right;
  constexpr double kBound = 3.3306690738754716e-16;  // (3 + 16 eps) eps, eps = 2^-53
  const double bound = kBound * (std::fabs(left) + std::fabs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return orientation_exact(a, b, c);
}
// Whether the closed segments [a, b] and [c, d] share at least one point; exactly.
bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

}  // namespace covsim
