#pragma once
// Ω shrunk by a distance: the points of Ω at least r from its boundary (Ω ⊖ r, the free space
// of a disk of radius r), from CGAL's straight-skeleton offset. Corners round which free space
// turns (an obstacle's corner) are mitered, not rounded: the result lies inside the exact
// Ω ⊖ r, by at most r (1 / sin(θ/2) − 1) at a corner of interior angle θ, so a body never
// comes nearer than r to a wall.
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

struct PolygonWithHoles {
  std::vector<Vec2> outer;               // counter-clockwise
  std::vector<std::vector<Vec2>> holes;  // clockwise
};

// The connected parts of the rings (outer counter-clockwise, holes clockwise, as Environment
// normalises them) shrunk by r > 0, in CGAL's order; empty when nothing is left. A narrow
// passage closes and splits a part in two.
std::vector<PolygonWithHoles> inset_polygon(const std::vector<std::vector<Vec2>>& rings, double r);

}  // namespace covsim
