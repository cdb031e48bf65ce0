#pragma once
// A region of a grid's square cells as an environment: how a robot that maps Ω on an
// occupancy grid believes Ω is (robot/occupancy_mapping.hpp). The region is the cells
// 4-connected to where the robots stand among the open ones; its outline is rectilinear, one
// outer ring and the holes of closed cells it surrounds.
#include <cstdint>
#include <memory>
#include <vector>

#include "core/vec2.hpp"
#include "geometry/environment.hpp"

namespace covsim {

// Cell (i, j) is the square [origin + (i, j) h, origin + (i + 1, j + 1) h].
struct CellGrid {
  Vec2 origin;
  double cell = 0.0;
  std::int32_t nx = 0, ny = 0;
  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::uint32_t index(std::int32_t i, std::int32_t j) const {
    return static_cast<std::uint32_t>(j * nx + i);
  }
  // The cell holding p (clamped to the grid).
  std::uint32_t cell_of(Vec2 p) const;
};

// Of the open cells (1 per cell, row-major), those 4-connected to a seed's cell; a seed on a
// closed cell starts from the nearest open cell (within 8 rings). Where two cells of the
// region meet only at a corner, the upper one is left out (and what it alone joined), so that
// the outline never touches itself. Empty (all 0) if no seed reaches an open cell.
std::vector<std::uint8_t> seeded_region(const CellGrid& grid, const std::vector<std::uint8_t>& open,
                                        const std::vector<Vec2>& seeds);

// The region's outline (its cell sides with a cell outside the region beyond), corners only,
// as an environment: the outer ring of the part holding the most cells, and the holes inside
// it. Throws GeometryError if the region is empty.
std::unique_ptr<Environment> region_environment(const CellGrid& grid,
                                                const std::vector<std::uint8_t>& region);

// The region's cells whose closed square lies at least `radius` from every cell outside it
// (and from the grid's edge): a union of cells inside the region shrunk by the radius, each
// 4-connected part as an environment (parted where cells meet only at a corner), largest
// first. Empty if none is left.
std::vector<std::unique_ptr<const Environment>> eroded_parts(
    const CellGrid& grid, const std::vector<std::uint8_t>& region, double radius);

}  // namespace covsim
