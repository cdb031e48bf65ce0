#pragma once
// The environment Ω: an outer polygon and any number of holes (free-standing obstacles),
// validated, normalised (outer ring counter-clockwise, holes clockwise, so that free space
// is on the left of every directed boundary edge), triangulated once, and indexed for the
// queries robots and planners make.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/vec2.hpp"
#include "geometry/free_space_mesh.hpp"
#include "geometry/grid_index.hpp"

namespace covsim {

struct BoundaryEdge {
  Vec2 a, b;            // free space on the left of a -> b
  std::uint32_t ring;   // 0: outer ring, h + 1: hole h
  std::uint32_t index;  // edge from vertex `index` to `index + 1` of that ring
  std::uint32_t component;
};

struct RayHit {
  Vec2 point;
  double distance;
  std::uint32_t edge;  // index into boundary()
};

class Environment {
 public:
  // Throws GeometryError naming the ring and the vertex or edge at fault: non-finite
  // coordinates, fewer than 3 distinct vertices, zero area, a self-intersecting ring, a hole
  // not strictly inside the outer ring, holes that overlap or touch. A repeated closing
  // vertex and repeated consecutive vertices are dropped.
  Environment(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes);

  const std::vector<Vec2>& outer() const { return rings_[0]; }
  std::size_t hole_count() const { return rings_.size() - 1; }
  const std::vector<Vec2>& hole(std::size_t h) const { return rings_[h + 1]; }
  // rings()[0] is the outer ring, rings()[h + 1] hole h, as normalised.
  const std::vector<std::vector<Vec2>>& rings() const { return rings_; }
  // Boundary edge k starts at mesh vertex k: rings are laid out in order in both.
  const std::vector<BoundaryEdge>& boundary() const { return boundary_; }
  const FreeSpaceMesh& mesh() const { return mesh_; }
  const GridIndex& triangle_index() const { return triangle_index_; }
  // Whether the box lies entirely inside Ω: it falls in cells of a fine mask (about 256
  // cells across Ω) that no boundary edge comes near and whose centres are in Ω.
  bool box_in_free_space(const Box& b) const;

  double area() const { return area_; }
  const Box& bounds() const { return bounds_; }
  double diameter() const { return diameter_; }  // of the bounding box
  // Distances below this count as zero: 1e-9 of the diameter.
  double tolerance() const { return tolerance_; }

  // The triangle of mesh() containing p (boundary included, within tolerance()).
  std::optional<std::uint32_t> locate(Vec2 p) const;
  // In a free cell of the mask, p is in Ω without a search.
  bool contains(Vec2 p) const;
  // The connected component of Ω containing p, if p is in Ω.
  std::optional<std::uint32_t> component_of(Vec2 p) const;
  std::uint32_t component_count() const { return mesh_.component_count; }

  // Whether the whole segment lies in Ω (touching the boundary is allowed).
  bool segment_inside(Vec2 a, Vec2 b) const;
  // Whether no boundary edge comes within `clearance` of the segment [a, b] (a line of sight
  // in free space with a margin).
  bool clear_of_boundary(Vec2 a, Vec2 b, double clearance) const;
  // The point of Ω closest to p: p itself when inside; otherwise on ∂Ω. With a component,
  // the closest point of that component.
  Vec2 closest_point(Vec2 p) const;
  Vec2 closest_point(Vec2 p, std::uint32_t component) const;
  // The distance from p to the nearest point of ∂Ω, inside Ω or out.
  double boundary_distance(Vec2 p) const;
  // How far a straight motion from `from` (in Ω) toward `to` gets before it would leave Ω:
  // `to` if the segment lies in Ω, else the point where it first leaves (the point of Ω
  // closest to `to` when it leaves only within rounding of `to`).
  Vec2 advance(Vec2 from, Vec2 to) const;
  // Boundary edges within tolerance() of p (two at a vertex of ∂Ω, one on an edge).
  std::vector<std::uint32_t> edges_at(Vec2 p) const;
  // Where a ray from origin along direction leaves Ω, within range (may be infinite).
  // Grazing a corner or running along a wall does not stop it. nullopt if it does not
  // leave Ω within range; origin must be in Ω.
  std::optional<RayHit> ray_cast(Vec2 origin, Vec2 direction, double range) const;

 private:
  std::optional<std::uint32_t> nearest_edge(Vec2 p, const std::uint32_t* component) const;
  // Sorted parameters t in [0, 1] where the segment meets ∂Ω, with 0 and 1 included.
  std::vector<double> boundary_crossings(Vec2 a, Vec2 b) const;

  std::vector<std::vector<Vec2>> rings_;
  std::vector<BoundaryEdge> boundary_;
  FreeSpaceMesh mesh_;
  GridIndex triangle_index_;
  GridIndex edge_index_;
  // The free-space mask: cells free_origin_ + (i, j) * free_cell_size_.
  std::vector<std::uint8_t> free_mask_;
  Vec2 free_origin_, free_cell_size_;
  std::int32_t free_nx_ = 0, free_ny_ = 0;
  Box bounds_;
  double area_ = 0.0;
  double diameter_ = 0.0;
  double tolerance_ = 0.0;
};

}  // namespace covsim
