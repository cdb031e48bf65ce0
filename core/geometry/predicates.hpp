#pragma once
// Exact geometric predicates (CGAL's filtered predicates, in one translation unit), for
// validation where a wrong answer would accept a bad polygon. Hot paths use plain doubles.
#include "core/geometry/vec2.hpp"

namespace covsim {

// +1 if a, b, c turn counter-clockwise, -1 if clockwise, 0 if collinear; exactly.
int orientation(Vec2 a, Vec2 b, Vec2 c);
// Whether the closed segments [a, b] and [c, d] share at least one point; exactly.
bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

}  // namespace covsim
