// The communication-graph part of a networked run's metrics sample: the edges the channel
// finds in reach and the graph's measures, for N robots at constant density (one per m² of
// a square, range 2.52 m: about 20 neighbours each). Beside it, the algorithm it replaced (a
// test of every pair, a search from every node, a dense eigensolver) for the ratio.
#include <benchmark/benchmark.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/connected_components.hpp>

#include <cmath>
#include <memory>
#include <numbers>

#include "core/random_stream.hpp"
#include "net/channel.hpp"
#include "net/comm_graph.hpp"

namespace {

// A square of n m² with n robots placed uniformly; the channel keeps a reference to it.
struct World {
  explicit World(std::size_t n)
      : side(std::sqrt(static_cast<double>(n))),
        square({{0, 0}, {side, 0}, {side, side}, {0, side}}, {}),
        channel(covsim::ChannelConfig{std::sqrt(20.0 / std::numbers::pi), false, nullptr, nullptr,
                                      nullptr},
                1, square) {
    covsim::RandomStream rng(1, n, "bench-robots");
    for (std::size_t i = 0; i < n; ++i)
      positions.push_back({rng.uniform(0.0, side), rng.uniform(0.0, side)});
  }
  double side;
  covsim::Environment square;
  covsim::Channel channel;
  std::vector<covsim::Vec2> positions;
};

// The measures as they were computed before: O(n (n + edges)) and O(n³).
covsim::CommGraphMetrics baseline_metrics(std::size_t n, const covsim::CommEdges& edges) {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  covsim::CommGraphMetrics m;
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
  std::vector<std::size_t> dist(n);
  for (std::size_t s = 0; s < n; ++s) {
    std::fill(dist.begin(), dist.end(), 0);
    boost::breadth_first_search(g, boost::vertex(s, g),
                                boost::visitor(boost::make_bfs_visitor(
                                    boost::record_distances(dist.data(), boost::on_tree_edge()))));
    m.diameter = std::max(m.diameter, *std::max_element(dist.begin(), dist.end()));
  }
  if (n >= 2) {
    m.algebraic_connectivity =
        m.components > 1 ? 0.0 : covsim::dense_algebraic_connectivity(n, edges);
  }
  return m;
}

void BM_CommGraphMetrics(benchmark::State& state) {
  const auto w = std::make_unique<World>(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    const covsim::CommEdges edges = covsim::communication_edges(w->channel, w->positions);
    benchmark::DoNotOptimize(covsim::comm_graph_metrics(w->positions.size(), edges));
  }
}

void BM_CommGraphMetricsBaseline(benchmark::State& state) {
  const auto w = std::make_unique<World>(static_cast<std::size_t>(state.range(0)));
  const std::size_t n = w->positions.size();
  for (auto _ : state) {
    covsim::CommEdges edges;
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = a + 1; b < n; ++b)
        if (w->channel.in_reach(w->positions[a], w->positions[b])) edges.emplace_back(a, b);
    benchmark::DoNotOptimize(baseline_metrics(n, edges));
  }
}

}  // namespace

BENCHMARK(BM_CommGraphMetrics)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CommGraphMetricsBaseline)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
