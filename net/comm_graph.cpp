#include "net/comm_graph.hpp"

#include <Eigen/Eigenvalues>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/connected_components.hpp>

#include <algorithm>

namespace covsim {

CommGraphMetrics comm_graph_metrics(
    std::size_t n, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  CommGraphMetrics m;
  if (n == 0) return m;
  Graph g(n);
  for (auto [a, b] : edges)
    boost::add_edge(a, b, g);

  std::vector<int> component(n);
  m.components = static_cast<std::size_t>(boost::connected_components(g, component.data()));
  std::vector<std::size_t> sizes(m.components, 0);
  for (int c : component)
    ++sizes[static_cast<std::size_t>(c)];
  m.largest_component = *std::max_element(sizes.begin(), sizes.end());
  m.average_degree = 2.0 * static_cast<double>(edges.size()) / static_cast<double>(n);

  // Hop distances by breadth-first search from every node.
  std::vector<std::size_t> dist(n);
  for (std::size_t s = 0; s < n; ++s) {
    std::fill(dist.begin(), dist.end(), 0);
    boost::breadth_first_search(g, boost::vertex(s, g),
                                boost::visitor(boost::make_bfs_visitor(
                                    boost::record_distances(dist.data(), boost::on_tree_edge()))));
    m.diameter = std::max(m.diameter, *std::max_element(dist.begin(), dist.end()));
  }

  if (n >= 2) {
    Eigen::MatrixXd laplacian =
        Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (auto [a, b] : edges) {
      laplacian(a, b) -= 1.0;
      laplacian(b, a) -= 1.0;
      laplacian(a, a) += 1.0;
      laplacian(b, b) += 1.0;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(laplacian, Eigen::EigenvaluesOnly);
    // Eigenvalues come sorted ascending; the smallest is 0 (up to rounding).
    m.algebraic_connectivity = m.components > 1 ? 0.0 : std::max(0.0, solver.eigenvalues()(1));
  }
  return m;
}

CommGraphMetrics complete_graph_metrics(std::size_t n) {
  CommGraphMetrics m;
  if (n == 0) return m;
  m.components = 1;
  m.largest_component = n;
  m.diameter = n >= 2 ? 1 : 0;
  m.average_degree = static_cast<double>(n - 1);
  m.algebraic_connectivity = n >= 2 ? static_cast<double>(n) : 0.0;
  return m;
}

}  // namespace covsim
