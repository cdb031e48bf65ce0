#pragma once
// Measures of the communication graph: robots are nodes, an edge joins two robots whose
// link is up (in range and, if required, in line of sight).
#include <cstdint>
#include <utility>
#include <vector>

namespace covsim {

struct CommGraphMetrics {
  std::size_t components = 0;
  std::size_t largest_component = 0;
  // The largest hop distance between two robots that can reach each other (0 for a graph
  // without edges); a disconnected graph has no finite diameter, so this is the largest
  // over its components.
  std::size_t diameter = 0;
  double average_degree = 0.0;
  // The second-smallest eigenvalue of the graph Laplacian: 0 exactly when disconnected.
  double algebraic_connectivity = 0.0;
};

// n nodes; edges as pairs of node indices (each once). Costs O(n (n + edges)) for the
// diameter (a search from every node) and O(n³) for the algebraic connectivity (a dense
// eigensolver).
CommGraphMetrics comm_graph_metrics(
    std::size_t n, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges);

// The same for the complete graph on n nodes (the ideal network: every robot hears every
// other), in closed form: one component, diameter 1, degree n - 1, and algebraic
// connectivity n (the Laplacian nI - J has eigenvalues 0 and n).
CommGraphMetrics complete_graph_metrics(std::size_t n);

}  // namespace covsim
