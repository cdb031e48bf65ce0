#pragma once
// Generators at one point split the cell they would share: with m of them at g, the one of
// rank k (their order: robot id) takes the wedge of directions from g at angles 2πk/m to
// 2π(k+1)/m from the x axis. The split is deterministic and every wedge has its own
// centroid, so coincident generators move apart at their next Lloyd step instead of moving
// together forever (a shared cell gives them one centroid).
#include <cstddef>

#include "geometry/convex_polygon.hpp"

namespace covsim {

// Clips a cell of the point g to the wedge of rank `rank` of `count` (count >= 2).
void clip_to_wedge(ConvexPolygon& cell, Vec2 g, std::size_t rank, std::size_t count);

}  // namespace covsim
