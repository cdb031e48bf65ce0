#pragma once
// Delaunay neighbours of a set of generators: the generators whose Voronoi cells share an
// edge. Computed with CGAL's Delaunay_triangulation_2 (batch insertion, spatially sorted).
#include <cstdint>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

struct DelaunayNeighbors {
  // Neighbours of generator i: index[start[i] .. start[i + 1]), in increasing order.
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> index;
};

// Throws GeometryError if two generators coincide (naming both) or one is not finite.
DelaunayNeighbors delaunay_neighbors(const std::vector<Vec2>& generators);

}  // namespace covsim
