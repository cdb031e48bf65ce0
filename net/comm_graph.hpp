#pragma once
// Measures of the communication graph: robots are nodes, an edge joins two robots whose
// link is up (in range and, if required, in line of sight).
#include <cstdint>
#include <utility>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

class Channel;

using CommEdges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

struct CommGraphMetrics {
  std::size_t components = 0;
  std::size_t largest_component = 0;
  // The largest hop distance between two robots that can reach each other (0 for a graph
  // without edges); a disconnected graph has no finite diameter, so this is the largest
  // over its components.
  std::size_t diameter = 0;
  double average_degree = 0.0;
  // The second-smallest eigenvalue of the graph Laplacian: 0 exactly when disconnected;
  // NaN when not computed (comm_graph_metrics told not to).
  double algebraic_connectivity = 0.0;
};

// Graphs up to this many nodes get the algebraic connectivity from a dense eigensolver;
// larger connected graphs from sparse shift-invert Lanczos.
inline constexpr std::size_t dense_spectrum_limit = 200;
// The sparse estimate stops when the residual of its Ritz pair is below this fraction of
// its Ritz value, which puts an eigenvalue of the Laplacian within that relative distance
// (measured: within 1e-12 of the dense solver on geometric graphs, 1e-9 on a path of 10 000
// nodes, where rounding in the solves dominates), or after 300 steps.
inline constexpr double algebraic_connectivity_tolerance = 1e-10;

// n nodes; edges as pairs of distinct node indices, each once, in any order.
// Components: O(n + edges). Diameter: exact, by iFUB (Crescenzi et al. 2013) from the
// centre of a 4-sweep, per component: a few searches on geometric graphs, O(n (n + edges))
// at worst. Algebraic connectivity: O(n³) dense up to dense_spectrum_limit nodes; above it,
// a sparse LDLᵀ factorisation of the grounded Laplacian (fill-reducing order, about
// O(n^1.5) for planar-like graphs) and a few tens of Lanczos steps on its inverse, within
// algebraic_connectivity_tolerance.
// Without `spectrum` a connected graph's algebraic connectivity is left NaN, and a sample
// costs O(n + edges) on graphs of bounded diameter.
CommGraphMetrics comm_graph_metrics(std::size_t n, const CommEdges& edges, bool spectrum = true);

// λ2 of the Laplacian of a connected graph on n ≥ 2 nodes from Eigen's dense symmetric
// eigensolver, O(n³): what comm_graph_metrics uses up to dense_spectrum_limit nodes, and the
// reference its sparse estimate is checked against.
double dense_algebraic_connectivity(std::size_t n, const CommEdges& edges);

// The same for the complete graph on n nodes (the ideal network: every robot hears every
// other), in closed form: one component, diameter 1, degree n - 1, and algebraic
// connectivity n (the Laplacian nI - J has eigenvalues 0 and n).
CommGraphMetrics complete_graph_metrics(std::size_t n);

// Pairs (a < b, sorted) of points whose squared distance is at most radius², found through
// a uniform grid of cells at least radius wide: O(n + pairs in neighbouring cells). A
// negative radius finds none. The test errs by a relative 1e-9 towards keeping a pair, so
// that a caller's own distance test can decide the borderline ones.
CommEdges pairs_within(const std::vector<Vec2>& points, double radius);

// The communication graph's edges (a < b, sorted): the pairs the channel finds in reach,
// each tested by Channel::in_reach as a test of every pair would; with a limited range only
// the pairs pairs_within the range are tested.
CommEdges communication_edges(const Channel& channel, const std::vector<Vec2>& positions);

}  // namespace covsim
