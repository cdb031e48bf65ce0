#pragma once
// A triangulation of the free space Ω as plain arrays: what every geometric query walks.
// Built once per environment by CGAL's constrained Delaunay triangulation.
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

struct FreeSpaceMesh {
  static constexpr std::int32_t kBoundary = -1;

  struct Triangle {
    std::array<std::uint32_t, 3> v;  // counter-clockwise
    // neighbor[i]: the triangle across edge i (from v[i+1] to v[i+2]), or kBoundary when
    // that edge is part of ∂Ω.
    std::array<std::int32_t, 3> neighbor;
  };

  std::vector<Vec2> vertices;  // the rings' vertices, in input order
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> component;  // per triangle: its connected component of Ω
  std::uint32_t component_count = 0;
  // The triangles around vertex v: star[star_start[v] .. star_start[v + 1]).
  std::vector<std::uint32_t> star_start;
  std::vector<std::uint32_t> star;

  Vec2 corner(std::uint32_t t, int i) const { return vertices[triangles[t].v[i % 3]]; }
  // The index j with triangles[other].neighbor[j] == t.
  int edge_towards(std::uint32_t other, std::uint32_t t) const;
};

// Triangulates the region inside rings[0] and outside rings[1..]. The rings must be valid
// (as checked by Environment); their vertices become mesh vertices in order.
FreeSpaceMesh triangulate_free_space(const std::vector<std::vector<Vec2>>& rings);

}  // namespace covsim
