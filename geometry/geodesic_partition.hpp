#pragma once
// Voronoi cells and the Lloyd step under the geodesic distance in Ω (the baseline of the
// paper's Section II-B2 and Fig. 2 b-d).
//
// Distances are exact: d_g(p, x) = |x - p| when the segment lies in Ω, otherwise the least
// d_g(p, v) + |x - v| over the reflex vertices v that x sees, with d_g(p, v) from Dijkstra on
// the visibility graph. Integrals over Ω use a lattice of spacing h (the midpoint rule: each
// lattice point of Ω carries φ(x) h²), so masses and moments carry an O(h) error from the
// cells cut by ∂Ω and by geodesic cell borders; on a square Ω with a uniform φ they are
// exact for linear integrands.
//
// The gradient of H_g = ½ Σ_i ∫_{V_i} d_g(p_i, x)² φ(x) dx for robot i is
// -∫_{V_i} d_g(p_i, x) u_i(x) φ(x) dx, with u_i(x) the unit direction in which the shortest
// path from p_i to x leaves p_i. The Lloyd-like step goes to
// t_i = p_i + (1 / M_i) ∫_{V_i} d_g u_i φ, which is the cell's centroid where the whole cell
// is in sight, and a compromise between the ways round an obstacle where it is not. t_i
// may lie outside Ω (Fig. 2d).
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/density.hpp"
#include "geometry/visibility_graph.hpp"

namespace covsim {

class GeodesicLattice {
 public:
  // Lattice points (i + ½, j + ½) h from the bounding box's corner that lie in Ω.
  GeodesicLattice(const VisibilityGraph& graph, const Density& density, double spacing);

  const VisibilityGraph& graph() const { return graph_; }
  double spacing() const { return h_; }
  const std::vector<Vec2>& points() const { return points_; }
  const std::vector<double>& weights() const { return weights_; }  // φ(x) h²
  // The reflex vertices point k sees.
  std::span<const VisibilityGraph::Link> links(std::size_t k) const {
    return {links_.data() + start_[k], links_.data() + start_[k + 1]};
  }
  double total_mass() const { return total_mass_; }

 private:
  const VisibilityGraph& graph_;
  double h_;
  std::vector<Vec2> points_;
  std::vector<double> weights_;
  std::vector<std::size_t> start_;
  std::vector<VisibilityGraph::Link> links_;
  double total_mass_ = 0.0;
};

struct GeodesicCell {
  double mass = 0.0;
  Vec2 target;        // p + (1 / M) ∫ d_g u φ; p itself for an empty cell
  Vec2 centroid;      // the cell's Euclidean centroid (p for an empty cell)
  double cost = 0.0;  // ½ ∫ d_g² φ
};

class GeodesicPartition {
 public:
  // Every lattice point goes to the generator closest in d_g (the lowest index on a tie).
  // Generators must lie in Ω; a lattice point no generator can reach (another component)
  // is left out.
  GeodesicPartition(const GeodesicLattice& lattice, std::vector<Vec2> generators);

  std::size_t size() const { return generators_.size(); }
  const std::vector<Vec2>& generators() const { return generators_; }
  const GeodesicCell& cell(std::size_t i) const { return cells_[i]; }
  // Which generator each lattice point belongs to (SIZE_MAX: unreachable).
  const std::vector<std::size_t>& owner() const { return owner_; }
  // The geodesic distance of each lattice point from its generator.
  const std::vector<double>& distance() const { return distance_; }
  double cost() const;  // H_g

 private:
  std::vector<Vec2> generators_;
  std::vector<GeodesicCell> cells_;
  std::vector<std::size_t> owner_;
  std::vector<double> distance_;
};

}  // namespace covsim
