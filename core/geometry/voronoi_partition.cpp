#include "core/geometry/voronoi_partition.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "core/geometry/delaunay.hpp"

namespace covsim {

VoronoiPartition::VoronoiPartition(const CellIntegrator& integrator, std::vector<Vec2> generators)
    : generators_(std::move(generators)) {
  const std::size_t n = generators_.size();
  const DelaunayNeighbors nb = delaunay_neighbors(generators_);
  start_.reserve(n + 1);
  start_.push_back(0);
  moments_.reserve(n);
  vertices_.reserve(6 * n);
  std::vector<Vec2> neighbors;
  ConvexPolygon cell;
  for (std::size_t i = 0; i < n; ++i) {
    neighbors.clear();
    for (std::uint32_t k = nb.start[i]; k < nb.start[i + 1]; ++k)
      neighbors.push_back(generators_[nb.index[k]]);
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
