#pragma once
// A uniform grid over a bounding box that buckets items (triangles, edges) by their
// bounding boxes. Queries report each item once, without mutable scratch state, so one
// index can serve several threads.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

class GridIndex {
 public:
  struct CellRange {
    std::int32_t i0, j0, i1, j1;  // inclusive
    bool empty() const { return i0 > i1 || j0 > j1; }
  };

  GridIndex() = default;
  // Roughly `per_cell` items per cell for items spread evenly over `bounds`.
  GridIndex(const std::vector<Box>& items, const Box& bounds, double per_cell = 2.0);

  std::int32_t nx() const { return nx_; }
  std::int32_t ny() const { return ny_; }
  Vec2 cell_size() const { return cell_; }
  const Box& bounds() const { return bounds_; }
  // The cells a box covers, clamped to the grid (empty if it misses the grid).
  CellRange cells(const Box& b) const;
  std::int32_t cell_index(std::int32_t i, std::int32_t j) const { return j * nx_ + i; }

  // Calls f(id) once for every item whose box overlaps the cells that b covers.
  template <class F>
  void query(const Box& b, F&& f) const {
    const CellRange q = cells(b);
    if (q.empty()) return;
    for (std::int32_t j = q.j0; j <= q.j1; ++j) {
      for (std::int32_t i = q.i0; i <= q.i1; ++i) {
        const std::int32_t c = cell_index(i, j);
        for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
          const std::uint32_t id = items_[k];
          const CellRange& r = ranges_[id];
          // Report an item only from the first cell where it meets the query.
          if (i == std::max(r.i0, q.i0) && j == std::max(r.j0, q.j0)) f(id);
        }
      }
    }
  }
  // Items in one cell (with repeats across cells).
  template <class F>
  void items_in_cell(std::int32_t i, std::int32_t j, F&& f) const {
    const std::int32_t c = cell_index(i, j);
    for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k)
      f(items_[k]);
  }

 private:
  Box bounds_;
  Vec2 cell_{1.0, 1.0};
  std::int32_t nx_ = 0, ny_ = 0;
  std::vector<CellRange> ranges_;  // per item
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> items_;
};

}  // namespace covsim
