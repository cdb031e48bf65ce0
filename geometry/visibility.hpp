#pragma once
// The part of ∂Ω visible from a point within a sensing range: what a range sensor gives a
// planner such as TangentBug.
#include <cstdint>
#include <vector>

#include "geometry/environment.hpp"

namespace covsim {

struct VisiblePiece {
  Vec2 a, b;           // a -> b runs counter-clockwise as seen from the viewpoint
  std::uint32_t edge;  // index into Environment::boundary()
};

struct VisibleBoundary {
  // Visible parts of boundary edges within range, in counter-clockwise order of direction
  // from the viewpoint; consecutive parts of one edge are merged. Edges through the
  // viewpoint (when it stands on the boundary) are included, seen edge-on.
  std::vector<VisiblePiece> pieces;
  // Where the visible boundary jumps, in the same order: a piece's end that is not the next
  // piece's start (an occluding vertex, the point behind it, or where a wall leaves the
  // sensing range). TangentBug's candidate points O_i.
  std::vector<Vec2> discontinuities;
  // The boundary edge each discontinuity point lies on (parallel to discontinuities).
  std::vector<std::uint32_t> discontinuity_edges;
};

// range may be 0 (nothing is sensed), finite, or infinite. Empty if p is not in Ω.
VisibleBoundary visible_boundary(const Environment& env, Vec2 p, double range);

}  // namespace covsim
