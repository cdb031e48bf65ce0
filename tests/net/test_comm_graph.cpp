#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>

#include "core/random_stream.hpp"
#include "net/channel.hpp"
#include "net/comm_graph.hpp"

using namespace covsim;

namespace {

// The measures as a search from every node and a dense eigensolver find them.
CommGraphMetrics brute_force_metrics(std::size_t n, const CommEdges& edges, bool spectrum) {
  CommGraphMetrics m;
  if (n == 0) return m;
  std::vector<std::vector<std::uint32_t>> adjacent(n);
  for (auto [a, b] : edges) {
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  std::vector<int> component(n, -1);
  for (std::uint32_t s = 0; s < n; ++s) {
    std::vector<std::size_t> hops(n, SIZE_MAX);
    std::queue<std::uint32_t> open;
    hops[s] = 0;
    open.push(s);
    std::size_t reached = 0;
    while (!open.empty()) {
      const std::uint32_t v = open.front();
      open.pop();
      ++reached;
      m.diameter = std::max(m.diameter, hops[v]);
      for (std::uint32_t w : adjacent[v]) {
        if (hops[w] != SIZE_MAX) continue;
        hops[w] = hops[v] + 1;
        open.push(w);
      }
    }
    m.largest_component = std::max(m.largest_component, reached);
    if (component[s] < 0) {
      ++m.components;
      for (std::uint32_t v = 0; v < n; ++v)
        if (hops[v] != SIZE_MAX) component[v] = static_cast<int>(s);
    }
  }
  m.average_degree = 2.0 * static_cast<double>(edges.size()) / static_cast<double>(n);
  if (spectrum && n >= 2 && m.components == 1) {
    m.algebraic_connectivity = dense_algebraic_connectivity(n, edges);
  }
  return m;
}

std::vector<Vec2> random_points(std::size_t n, double side, std::uint64_t seed) {
  RandomStream rng(seed, n, "test-points");
  std::vector<Vec2> points(n);
  for (Vec2& p : points)
    p = {rng.uniform(0.0, side), rng.uniform(0.0, side)};
  return points;
}

CommEdges all_pairs_within(const std::vector<Vec2>& points, double radius) {
  CommEdges pairs;
  for (std::uint32_t a = 0; a < points.size(); ++a)
    for (std::uint32_t b = a + 1; b < points.size(); ++b)
      if (distance(points[a], points[b]) <= radius) pairs.emplace_back(a, b);
  return pairs;
}

// A random geometric graph: n points in the unit square, joined within `radius`.
CommEdges geometric_graph(std::size_t n, double radius, std::uint64_t seed) {
  return all_pairs_within(random_points(n, 1.0, seed), radius);
}

CommEdges path_graph(std::size_t n) {
  CommEdges e;
  for (std::uint32_t v = 0; v + 1 < n; ++v)
    e.emplace_back(v, v + 1);
  return e;
}

CommEdges cycle_graph(std::size_t n) {
  CommEdges e = path_graph(n);
  e.emplace_back(0, static_cast<std::uint32_t>(n - 1));
  return e;
}

CommEdges star_graph(std::size_t n) {
  CommEdges e;
  for (std::uint32_t v = 1; v < n; ++v)
    e.emplace_back(0, v);
  return e;
}

CommEdges complete_graph(std::size_t n) {
  CommEdges e;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      e.emplace_back(a, b);
  return e;
}

// Each node joined to one earlier node at random (a random tree), in a random order.
CommEdges random_tree(std::size_t n, std::uint64_t seed) {
  RandomStream rng(seed, n, "test-tree");
  CommEdges e;
  for (std::uint32_t v = 1; v < n; ++v)
    e.emplace_back(static_cast<std::uint32_t>(rng.below(v)), v);
  for (std::size_t k = e.size(); k > 1; --k)
    std::swap(e[k - 1], e[rng.below(k)]);
  return e;
}

// Each pair joined with probability p (Erdős–Rényi).
CommEdges random_graph(std::size_t n, double p, std::uint64_t seed) {
  RandomStream rng(seed, n, "test-random-graph");
  CommEdges e;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (rng.bernoulli(p)) e.emplace_back(a, b);
  return e;
}

// Two graphs side by side, without edges between them.
CommEdges disjoint_union(std::size_t n, const CommEdges& a, const CommEdges& b) {
  CommEdges e = a;
  for (auto [x, y] : b)
    e.emplace_back(static_cast<std::uint32_t>(x + n), static_cast<std::uint32_t>(y + n));
  return e;
}

struct Case {
  std::string name;
  std::size_t n;
  CommEdges edges;
};

std::vector<Case> structural_cases() {
  std::vector<Case> cases;
  for (std::size_t n : {0, 1, 2, 3, 7, 50, 201, 1000, 3000}) {
    cases.push_back({"path", n, path_graph(n)});
    cases.push_back({"star", n, star_graph(n)});
    cases.push_back({"tree", n, random_tree(n, 1)});
    cases.push_back({"empty", n, {}});
  }
  for (std::size_t n : {3, 4, 9, 10, 401, 2000})
    cases.push_back({"cycle", n, cycle_graph(n)});
  std::uint64_t seed = 0;
  // From below the percolation threshold (many odd-shaped components) to well connected.
  for (std::size_t n : {20, 100, 300, 1000, 3000}) {
    for (double degree : {2.0, 4.5, 8.0, 20.0}) {
      const double radius = std::sqrt(degree / (std::numbers::pi * static_cast<double>(n)));
      for (int k = n < 3000 ? 0 : 2; k < 3; ++k)
        cases.push_back({"geometric", n, geometric_graph(n, radius, ++seed)});
    }
  }
  for (std::size_t n : {30, 250, 800})
    for (double degree : {0.8, 1.5, 6.0})
      cases.push_back({"random", n, random_graph(n, degree / static_cast<double>(n), ++seed)});
  cases.push_back(
      {"path and cycle", 1500, disjoint_union(1000, path_graph(1000), cycle_graph(500))});
  cases.push_back(
      {"two trees", 600, disjoint_union(300, random_tree(300, 2), random_tree(300, 3))});
  return cases;
}

// pairs_within's contract: every pair within the radius, and besides them only pairs
// within a relative 1e-9 of it, sorted.
void check_pairs_within(const std::vector<Vec2>& points, double radius) {
  const CommEdges got = pairs_within(points, radius);
  const CommEdges within = all_pairs_within(points, radius);
  const CommEdges near = all_pairs_within(points, radius * (1.0 + 1e-9));
  CHECK(std::is_sorted(got.begin(), got.end()));
  CHECK(std::includes(got.begin(), got.end(), within.begin(), within.end()));
  CHECK(std::includes(near.begin(), near.end(), got.begin(), got.end()));
  CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
}

}  // namespace

TEST_CASE("components, largest component and diameter equal a search from every node",
          "[net][comm_graph]") {
  for (const Case& c : structural_cases()) {
    INFO(c.name << " on " << c.n << " nodes, " << c.edges.size() << " edges");
    const CommGraphMetrics got = comm_graph_metrics(c.n, c.edges);
    const CommGraphMetrics want = brute_force_metrics(c.n, c.edges, false);
    CHECK(got.components == want.components);
    CHECK(got.largest_component == want.largest_component);
    CHECK(got.diameter == want.diameter);
    CHECK(got.average_degree == want.average_degree);
    if (want.components != 1) CHECK(got.algebraic_connectivity == 0.0);
  }
}

TEST_CASE("the algebraic connectivity agrees with the dense eigensolver", "[net][comm_graph]") {
  std::uint64_t seed = 100;
  std::vector<Case> cases;
  for (std::size_t n : {2, 3, 60, 200, 201, 260, 400}) {
    for (double degree : {5.0, 12.0, 30.0}) {
      const double radius = std::sqrt(degree / (std::numbers::pi * static_cast<double>(n)));
      cases.push_back({"geometric", n, geometric_graph(n, radius, ++seed)});
    }
    cases.push_back({"tree", n, random_tree(n, ++seed)});
    cases.push_back(
        {"random", n, random_graph(n, std::min(1.0, 8.0 / static_cast<double>(n)), ++seed)});
  }
  cases.push_back({"path", 350, path_graph(350)});
  cases.push_back(
      {"split geometric", 500,
       disjoint_union(250, geometric_graph(250, 0.2, 1), geometric_graph(250, 0.2, 2))});
  std::size_t connected_above_limit = 0;
  for (const Case& c : cases) {
    INFO(c.name << " on " << c.n << " nodes, " << c.edges.size() << " edges");
    const CommGraphMetrics got = comm_graph_metrics(c.n, c.edges);
    const CommGraphMetrics want = brute_force_metrics(c.n, c.edges, true);
    REQUIRE(got.components == want.components);
    if (want.components > 1) {
      CHECK(got.algebraic_connectivity == 0.0);
      continue;
    }
    if (c.n > dense_spectrum_limit) ++connected_above_limit;
    if (c.n <= dense_spectrum_limit) {
      CHECK(got.algebraic_connectivity == want.algebraic_connectivity);
    } else {
      CHECK(std::abs(got.algebraic_connectivity - want.algebraic_connectivity) <=
            1e-8 * want.algebraic_connectivity + 1e-12);
    }
  }
  CHECK(connected_above_limit >= 10);  // the sparse solver was exercised
}

TEST_CASE("the algebraic connectivity of paths, cycles, stars and complete graphs",
          "[net][comm_graph]") {
  const double pi = std::numbers::pi;
  auto close_to = [](double got, double want) {
    INFO("got " << got << ", want " << want);
    CHECK(std::abs(got - want) <= 1e-8 * want);
  };
  for (std::size_t n : {2, 5, 150, 200, 201, 500, 1000, 3000}) {
    INFO(n << " nodes");
    const double nd = static_cast<double>(n);
    close_to(comm_graph_metrics(n, path_graph(n)).algebraic_connectivity,
             2.0 * (1.0 - std::cos(pi / nd)));
    if (n >= 3) {
      close_to(comm_graph_metrics(n, cycle_graph(n)).algebraic_connectivity,
               2.0 * (1.0 - std::cos(2.0 * pi / nd)));
      close_to(comm_graph_metrics(n, star_graph(n)).algebraic_connectivity, 1.0);
    }
    if (n <= 500) {
      close_to(comm_graph_metrics(n, complete_graph(n)).algebraic_connectivity, nd);
      CHECK(complete_graph_metrics(n).algebraic_connectivity == nd);
    }
  }
}

TEST_CASE("the sparse algebraic connectivity is the same on every call", "[net][comm_graph]") {
  const CommEdges edges = geometric_graph(1500, 0.07, 9);
  const CommGraphMetrics a = comm_graph_metrics(1500, edges);
  REQUIRE(a.components == 1);
  CHECK(a.algebraic_connectivity > 0.0);
  CHECK(comm_graph_metrics(1500, edges).algebraic_connectivity == a.algebraic_connectivity);
}

TEST_CASE("without the spectrum a connected graph's λ2 is NaN and the rest is unchanged",
          "[net][comm_graph]") {
  for (std::size_t n : {1500, 40}) {
    const CommEdges edges = geometric_graph(n, n > 100 ? 0.07 : 0.02, 3);
    const CommGraphMetrics with = comm_graph_metrics(n, edges);
    const CommGraphMetrics without = comm_graph_metrics(n, edges, false);
    CHECK(without.components == with.components);
    CHECK(without.largest_component == with.largest_component);
    CHECK(without.diameter == with.diameter);
    CHECK(without.average_degree == with.average_degree);
    if (with.components == 1) {
      CHECK(with.algebraic_connectivity > 0.0);
      CHECK(std::isnan(without.algebraic_connectivity));
    } else {  // disconnected: 0 without any eigensolver
      CHECK(without.algebraic_connectivity == 0.0);
    }
  }
}

TEST_CASE("pairs within a radius through the grid equal those of every pair", "[net][comm_graph]") {
  std::uint64_t seed = 500;
  for (std::size_t n : {0, 1, 2, 40, 700, 2500}) {
    for (double radius : {0.0, 0.003, 0.05, 0.3, 2.0}) {
      INFO(n << " points within " << radius);
      const std::vector<Vec2> points = random_points(n, 1.0, ++seed);
      // Random points are nowhere near the borderline: exactly the same pairs.
      CHECK(pairs_within(points, radius) == all_pairs_within(points, radius));
    }
  }
  // On a lattice whose spacing is the radius every neighbour is at the radius (up to
  // rounding either way), and coincident points are at distance 0.
  std::vector<Vec2> lattice;
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i)
      lattice.push_back({0.1 * i + 0.3, 0.1 * j - 7.0});
  lattice.push_back(lattice[17]);
  lattice.push_back(lattice[17]);
  for (double radius : {0.0, 0.1, 0.1 * std::sqrt(2.0), 0.25}) {
    INFO("lattice within " << radius);
    check_pairs_within(lattice, radius);
    CHECK(pairs_within(lattice, radius).size() >= all_pairs_within(lattice, radius).size());
  }
  // A tight cluster and a far outlier: the grid's cells stay few.
  std::vector<Vec2> clustered = random_points(300, 1e-3, 3);
  clustered.push_back({1e6, -1e6});
  check_pairs_within(clustered, 5e-4);
  check_pairs_within(clustered, 3e6);
  CHECK(pairs_within(clustered, 3e6).size() == 301 * 300 / 2);
  CHECK(pairs_within(random_points(50, 1.0, 4), -1.0).empty());
}

TEST_CASE("the communication graph's edges through the grid equal a test of every pair",
          "[net][comm_graph]") {
  // A room with a wall in the middle: line of sight removes some pairs that are in range.
  const Environment room({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 2}, {6, 2}, {6, 8}, {4, 8}}});
  std::vector<Vec2> positions;
  RandomStream rng(8, 0, "test-positions");
  while (positions.size() < 600) {
    const Vec2 p{rng.uniform(0.0, 10.0), rng.uniform(0.0, 10.0)};
    if (room.contains(p)) positions.push_back(p);
  }
  for (std::optional<double> range : {std::optional<double>{}, std::optional<double>{0.8},
                                      std::optional<double>{2.5}, std::optional<double>{30.0}}) {
    for (bool line_of_sight : {false, true}) {
      INFO("range " << (range ? *range : -1.0) << ", line of sight " << line_of_sight);
      const Channel channel(ChannelConfig{range, line_of_sight, nullptr, nullptr, nullptr}, 1,
                            room);
      CommEdges every_pair;
      for (std::uint32_t a = 0; a < positions.size(); ++a)
        for (std::uint32_t b = a + 1; b < positions.size(); ++b)
          if (channel.in_reach(positions[a], positions[b])) every_pair.emplace_back(a, b);
      const CommEdges grid = communication_edges(channel, positions);
      CHECK(grid == every_pair);
      CHECK(!grid.empty());
    }
  }
}
