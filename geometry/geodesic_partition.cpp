#include "geometry/geodesic_partition.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace covsim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kNobody = std::numeric_limits<std::size_t>::max();
}  // namespace

GeodesicLattice::GeodesicLattice(const VisibilityGraph& graph, const Density& density,
                                 double spacing)
    : graph_(graph), h_(spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument("geodesic lattice spacing must be a positive number");
  const Environment& env = graph.environment();
  const Box& b = env.bounds();
  const auto nx = static_cast<std::int64_t>(std::ceil(b.size().x / h_));
  const auto ny = static_cast<std::int64_t>(std::ceil(b.size().y / h_));
  if (nx * ny > (std::int64_t{1} << 22))
    throw std::invalid_argument("geodesic lattice spacing too fine: more than 2^22 points");
  start_.push_back(0);
  for (std::int64_t j = 0; j < ny; ++j) {
    for (std::int64_t i = 0; i < nx; ++i) {
      const Vec2 x =
          b.lo + Vec2{(static_cast<double>(i) + 0.5) * h_, (static_cast<double>(j) + 0.5) * h_};
      if (!env.contains(x)) continue;
      points_.push_back(x);
      weights_.push_back(density(x) * h_ * h_);
      total_mass_ += weights_.back();
      for (const VisibilityGraph::Link& l : graph.visible_from(x))
        links_.push_back(l);
      start_.push_back(links_.size());
    }
  }
}

GeodesicPartition::GeodesicPartition(const GeodesicLattice& lattice, std::vector<Vec2> generators)
    : generators_(std::move(generators)) {
  const VisibilityGraph& graph = lattice.graph();
  const Environment& env = graph.environment();
  const std::vector<Vec2>& xs = lattice.points();
  owner_.assign(xs.size(), kNobody);
  distance_.assign(xs.size(), kInf);
  std::vector<Vec2> direction(xs.size());
  std::vector<GeodesicTree> trees;
  for (Vec2 p : generators_)
    trees.push_back(graph.tree(p));
  // Point by point, generators in order of straight-line distance: d_g >= |x - p|, so once
  // that exceeds the best geodesic distance found, no later generator can win, and the
  // nearest generator is usually in sight.
  std::vector<std::pair<double, std::size_t>> order(generators_.size());
  for (std::size_t k = 0; k < xs.size(); ++k) {
    for (std::size_t i = 0; i < generators_.size(); ++i)
      order[i] = {norm2(generators_[i] - xs[k]), i};
    std::sort(order.begin(), order.end());
    for (const auto& [straight2, i] : order) {
      // Squared distances order the generators; the margin keeps rounding from cutting off
      // a generator at the same distance (which may win the tie).
      if (straight2 > distance_[k] * distance_[k] * (1.0 + 1e-12)) break;
      const Vec2 p = generators_[i];
      const double straight = covsim::distance(p, xs[k]);
      double d = kInf;
      Vec2 u;
      if (env.segment_inside(p, xs[k])) {
        d = straight;
        u = straight > 0.0 ? (xs[k] - p) / straight : Vec2{0, 0};
      } else {
        const GeodesicTree& tree = trees[i];
        std::uint32_t via = 0;
        for (const VisibilityGraph::Link& l : lattice.links(k)) {
          const double dv = tree.distance[l.to] + l.length;
          if (dv < d) {
            d = dv;
            via = l.to;
          }
        }
        if (d < kInf) {
          const Vec2 first = graph.vertices()[tree.first[via]];
          const double n = covsim::distance(first, p);
          u = n > 0.0 ? (first - p) / n : Vec2{0, 0};
        }
      }
      // The lowest index wins a tie.
      if (d < distance_[k] || (d == distance_[k] && d < kInf && i < owner_[k])) {
        distance_[k] = d;
        owner_[k] = i;
        direction[k] = u;
      }
    }
  }
  cells_.assign(generators_.size(), GeodesicCell{});
  std::vector<Vec2> pull(generators_.size(), Vec2{0, 0}), first(generators_.size(), Vec2{0, 0});
  for (std::size_t k = 0; k < xs.size(); ++k) {
    if (owner_[k] == kNobody) continue;
    const double w = lattice.weights()[k];
    GeodesicCell& c = cells_[owner_[k]];
    c.mass += w;
    c.cost += 0.5 * w * distance_[k] * distance_[k];
    pull[owner_[k]] = pull[owner_[k]] + (w * distance_[k]) * direction[k];
    first[owner_[k]] = first[owner_[k]] + w * (xs[k] - generators_[owner_[k]]);
  }
  for (std::size_t i = 0; i < generators_.size(); ++i) {
    GeodesicCell& c = cells_[i];
    const Vec2 p = generators_[i];
    c.target = c.mass > 0.0 ? p + pull[i] / c.mass : p;
    c.centroid = c.mass > 0.0 ? p + first[i] / c.mass : p;
  }
}

double GeodesicPartition::cost() const {
  double h = 0.0;
  for (const GeodesicCell& c : cells_)
    h += c.cost;
  return h;
}

}  // namespace covsim
