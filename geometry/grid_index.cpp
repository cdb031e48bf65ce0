#include "geometry/grid_index.hpp"

namespace covsim {

GridIndex::GridIndex(const std::vector<Box>& items, const Box& bounds, double per_cell)
    : bounds_(bounds) {
  const Vec2 size = bounds.size();
  const double area = std::max(size.x * size.y, 1e-300);
  const double cells_wanted = std::clamp(static_cast<double>(items.size()) / per_cell, 1.0, 1e6);
  const double side = std::sqrt(area / cells_wanted);
  nx_ = static_cast<std::int32_t>(std::clamp(std::ceil(size.x / side), 1.0, 4096.0));
  ny_ = static_cast<std::int32_t>(std::clamp(std::ceil(size.y / side), 1.0, 4096.0));
  cell_ = {size.x / nx_, size.y / ny_};
  if (!(cell_.x > 0.0)) cell_.x = 1.0;
  if (!(cell_.y > 0.0)) cell_.y = 1.0;

  ranges_.reserve(items.size());
  std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (const Box& b : items) {
    ranges_.push_back(cells(b));
    const CellRange& r = ranges_.back();
    for (std::int32_t j = r.j0; j <= r.j1; ++j) {
      for (std::int32_t i = r.i0; i <= r.i1; ++i)
        ++count[static_cast<std::size_t>(cell_index(i, j))];
    }
  }
  start_.assign(count.size(), 0);
  for (std::size_t c = 1; c < count.size(); ++c)
    start_[c] = start_[c - 1] + count[c - 1];
  items_.resize(start_.back());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::uint32_t id = 0; id < ranges_.size(); ++id) {
    const CellRange& r = ranges_[id];
    for (std::int32_t j = r.j0; j <= r.j1; ++j) {
      for (std::int32_t i = r.i0; i <= r.i1; ++i)
        items_[fill[static_cast<std::size_t>(cell_index(i, j))]++] = id;
    }
  }
}

GridIndex::CellRange GridIndex::cells(const Box& b) const {
  if (b.empty() || !b.overlaps(bounds_)) return {0, 0, -1, -1};
  auto clampi = [](double v, std::int32_t n) {
    return static_cast<std::int32_t>(std::clamp(std::floor(v), 0.0, static_cast<double>(n - 1)));
  };
  return {clampi((b.lo.x - bounds_.lo.x) / cell_.x, nx_),
          clampi((b.lo.y - bounds_.lo.y) / cell_.y, ny_),
          clampi((b.hi.x - bounds_.lo.x) / cell_.x, nx_),
          clampi((b.hi.y - bounds_.lo.y) / cell_.y, ny_)};
}

}  // namespace covsim
