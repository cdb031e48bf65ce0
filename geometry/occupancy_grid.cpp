#include "geometry/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace covsim {

namespace {
// Whether the closed segment a-b meets the closed box (Liang-Barsky clipping).
bool segment_meets_box(Vec2 a, Vec2 b, const Box& box) {
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  const auto clip = [&](double p, double q) {  // p t <= q
    if (p == 0.0) return q >= 0.0;
    const double t = q / p;
    if (p < 0.0) {
      if (t > t1) return false;
      t0 = std::max(t0, t);
    } else {
      if (t < t0) return false;
      t1 = std::min(t1, t);
    }
    return true;
  };
  return clip(-d.x, a.x - box.lo.x) && clip(d.x, box.hi.x - a.x) && clip(-d.y, a.y - box.lo.y) &&
         clip(d.y, box.hi.y - a.y);
}
}  // namespace

OccupancyGrid::OccupancyGrid(const Environment& env, double resolution)
    : env_(env), h_(resolution), origin_(env.bounds().lo) {
  if (!(resolution > 0.0) || !std::isfinite(resolution))
    throw std::invalid_argument("grid resolution must be a positive number");
  const Vec2 size = env.bounds().size();
  const double nx = std::ceil(size.x / h_), ny = std::ceil(size.y / h_);
  if (nx * ny > double(1 << 24))
    throw std::invalid_argument("grid resolution too fine: more than 2^24 cells");
  nx_ = std::max<std::int32_t>(1, static_cast<std::int32_t>(nx));
  ny_ = std::max<std::int32_t>(1, static_cast<std::int32_t>(ny));
  free_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), 1);
  // Cells a boundary edge touches are blocked; the margin keeps a rounding error from
  // freeing a cell an edge grazes.
  const double margin = env.tolerance();
  for (const BoundaryEdge& e : env.boundary()) {
    const auto lo_i =
        static_cast<std::int32_t>(std::floor((std::min(e.a.x, e.b.x) - margin - origin_.x) / h_));
    const auto hi_i =
        static_cast<std::int32_t>(std::floor((std::max(e.a.x, e.b.x) + margin - origin_.x) / h_));
    const auto lo_j =
        static_cast<std::int32_t>(std::floor((std::min(e.a.y, e.b.y) - margin - origin_.y) / h_));
    const auto hi_j =
        static_cast<std::int32_t>(std::floor((std::max(e.a.y, e.b.y) + margin - origin_.y) / h_));
    for (std::int32_t j = std::max(0, lo_j); j <= std::min(ny_ - 1, hi_j); ++j) {
      for (std::int32_t i = std::max(0, lo_i); i <= std::min(nx_ - 1, hi_i); ++i) {
        if (free_[index(i, j)] == 0) continue;
        Box box;
        box.lo = origin_ + Vec2{i * h_ - margin, j * h_ - margin};
        box.hi = origin_ + Vec2{(i + 1) * h_ + margin, (j + 1) * h_ + margin};
        if (segment_meets_box(e.a, e.b, box)) free_[index(i, j)] = 0;
      }
    }
  }
  for (std::uint32_t c = 0; c < free_.size(); ++c) {
    if (free_[c] != 0 && !env.contains(center(c))) free_[c] = 0;
  }
}

Vec2 OccupancyGrid::center(std::uint32_t c) const {
  return origin_ + Vec2{(column(c) + 0.5) * h_, (row(c) + 0.5) * h_};
}

std::size_t OccupancyGrid::free_count() const {
  return static_cast<std::size_t>(std::count(free_.begin(), free_.end(), std::uint8_t{1}));
}

std::optional<std::uint32_t> OccupancyGrid::nearest_free(Vec2 p, std::int32_t max_rings) const {
  const auto pi = static_cast<std::int32_t>(std::floor((p.x - origin_.x) / h_));
  const auto pj = static_cast<std::int32_t>(std::floor((p.y - origin_.y) / h_));
  std::optional<std::uint32_t> best;
  double best_d = INFINITY;
  // Ring r holds the cells at Chebyshev distance r; a cell of ring r is at least (r - 1) h
  // away, so once that exceeds the best distance found no later ring can do better.
  for (std::int32_t r = 0; r <= max_rings; ++r) {
    if (best && (r - 1) * h_ > best_d) break;
    for (std::int32_t j = pj - r; j <= pj + r; ++j) {
      for (std::int32_t i = pi - r; i <= pi + r; ++i) {
        if (std::max(std::abs(i - pi), std::abs(j - pj)) != r || !free(i, j)) continue;
        const std::uint32_t c = index(i, j);
        const double d = distance(p, center(c));
        if (d < best_d && env_.segment_inside(p, center(c))) {
          best_d = d;
          best = c;
        }
      }
    }
  }
  return best;
}

}  // namespace covsim
