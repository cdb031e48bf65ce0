#pragma once
// Checks and normalises the rings of an environment; errors are GeometryError with a
// message naming the ring ("outer ring", "hole 2") and the vertex or edge at fault.
#include <string>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

// Drops a repeated closing vertex and repeated consecutive vertices, checks coordinates,
// vertex count, area and simplicity, and orients the ring counter-clockwise (or clockwise).
std::vector<Vec2> normalize_ring(std::vector<Vec2> ring, std::size_t ring_index,
                                 bool counter_clockwise);
// Checks every hole lies strictly inside the outer ring and no two holes overlap or touch.
void check_hole_placement(const std::vector<std::vector<Vec2>>& rings);
// Crossing-number test; meaningful for points not on the ring.
bool inside_ring(const std::vector<Vec2>& ring, Vec2 p);
std::string ring_name(std::size_t ring);  // 0 -> "outer ring", h + 1 -> "hole h"

}  // namespace covsim
