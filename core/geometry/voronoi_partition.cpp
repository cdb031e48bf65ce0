#include "core/geometry/voronoi_partition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "core/geometry/delaunay.hpp"

namespace covsim {

VoronoiPartition::VoronoiPartition(const CellIntegrator& integrator, std::vector<Vec2> generators,
                                   Coincident coincident)
    : generators_(std::move(generators)) {
  const std::size_t n = generators_.size();
  // With sharing, the Delaunay triangulation is of the distinct generators; first[i] is the
  // index among them of generator i, or -1 for a repeat of an earlier one.
  std::vector<Vec2> distinct = generators_;
  std::vector<std::int64_t> first(n);
  for (std::size_t i = 0; i < n; ++i)
    first[i] = static_cast<std::int64_t>(i);
  if (coincident == Coincident::share) {
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i)
      order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const Vec2 p = generators_[a], q = generators_[b];
      return std::tie(p.x, p.y, a) < std::tie(q.x, q.y, b);
    });
    std::vector<bool> repeat(n, false);
    for (std::size_t k = 1; k < n; ++k)
      repeat[order[k]] = generators_[order[k]] == generators_[order[k - 1]];
    distinct.clear();
    for (std::size_t i = 0; i < n; ++i) {
      first[i] = repeat[i] ? -1 : static_cast<std::int64_t>(distinct.size());
      if (!repeat[i]) distinct.push_back(generators_[i]);
    }
  }
  const DelaunayNeighbors nb = delaunay_neighbors(distinct);
  start_.reserve(n + 1);
  start_.push_back(0);
  moments_.reserve(n);
  vertices_.reserve(6 * n);
  std::vector<Vec2> neighbors;
  ConvexPolygon cell;
  for (std::size_t i = 0; i < n; ++i) {
    if (first[i] < 0) {
      start_.push_back(vertices_.size());
      moments_.push_back(Moments{});
      continue;
    }
    const auto d = static_cast<std::size_t>(first[i]);
    neighbors.clear();
    for (std::uint32_t k = nb.start[d]; k < nb.start[d + 1]; ++k)
      neighbors.push_back(distinct[nb.index[k]]);
    integrator.cell(generators_[i], neighbors, cell);
    vertices_.insert(vertices_.end(), cell.begin(), cell.end());
    start_.push_back(vertices_.size());
    moments_.push_back(integrator.integrate(cell, generators_[i]));
  }
}

double VoronoiPartition::cost(std::span<const Vec2> points) const {
  if (points.size() != generators_.size()) {
    throw std::invalid_argument(
        fmt::format("cost of {} points on a partition of {} cells", points.size(), size()));
  }
  double h = 0.0;
  for (std::size_t i = 0; i < size(); ++i)
    h += 0.5 * shift_moments(moments_[i], generators_[i], points[i]).second;
  return h;
}

}  // namespace covsim
