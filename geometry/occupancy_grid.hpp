#pragma once
// Ω rasterised to square cells, for map-based planners. A cell is free only if its closed
// square lies in Ω: no boundary edge touches it and its centre is in Ω. The rule is
// conservative, so straight moves between the centres of free cells (side by side, or
// diagonal with both side cells free) stay in Ω; passages narrower than about two cells can
// be closed off.
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/environment.hpp"

namespace covsim {

class OccupancyGrid {
 public:
  // Cells of side `resolution` (metres) from the lower-left corner of Ω's bounding box.
  // Throws std::invalid_argument if the grid would have more than 2^24 cells.
  OccupancyGrid(const Environment& env, double resolution);

  double resolution() const { return h_; }
  std::int32_t nx() const { return nx_; }
  std::int32_t ny() const { return ny_; }
  std::size_t size() const { return free_.size(); }
  std::uint32_t index(std::int32_t i, std::int32_t j) const {
    return static_cast<std::uint32_t>(j * nx_ + i);
  }
  std::int32_t column(std::uint32_t c) const { return static_cast<std::int32_t>(c) % nx_; }
  std::int32_t row(std::uint32_t c) const { return static_cast<std::int32_t>(c) / nx_; }
  bool free(std::uint32_t c) const { return free_[c] != 0; }
  bool free(std::int32_t i, std::int32_t j) const {
    return i >= 0 && j >= 0 && i < nx_ && j < ny_ && free_[index(i, j)] != 0;
  }
  Vec2 center(std::uint32_t c) const;
  std::size_t free_count() const;
  // The free cell whose centre is closest to p among those p sees in a straight line (in
  // Ω), searching rings of cells outward up to `max_rings`; nullopt if none.
  std::optional<std::uint32_t> nearest_free(Vec2 p, std::int32_t max_rings = 8) const;

 private:
  const Environment& env_;
  double h_;
  Vec2 origin_;
  std::int32_t nx_ = 0, ny_ = 0;
  std::vector<std::uint8_t> free_;
};

}  // namespace covsim
