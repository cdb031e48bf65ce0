#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/random_stream.hpp"
#include "geometry/geometry_error.hpp"
#include "geometry/uniform_density.hpp"
#include "geometry/voronoi_partition.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

namespace {

struct World {
  Environment env;
  UniformDensity density;
  CellIntegrator cells;
  World(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes)
      : env(std::move(outer), std::move(holes)), cells(env, density) {}
};

void check_summary(const CellSummary& s, double mass, Vec2 centroid, double cost) {
  CHECK(s.mass == Approx(mass).epsilon(1e-12));
  CHECK(s.centroid.x == Approx(centroid.x).epsilon(1e-12).margin(1e-12));
  CHECK(s.centroid.y == Approx(centroid.y).epsilon(1e-12).margin(1e-12));
  CHECK(s.cost == Approx(cost).epsilon(1e-12).margin(1e-12));
}
}  // namespace

TEST_CASE("a square split in two", "[cells]") {
  World w(square(0, 0, 2, 1), {});
  VoronoiPartition part(w.cells, {{0.5, 0.5}, {1.5, 0.5}});
  check_summary(part.summary(0), 1.0, {0.5, 0.5}, 1.0 / 12.0);
  check_summary(part.summary(1), 1.0, {1.5, 0.5}, 1.0 / 12.0);
  CHECK(part.cost() == Approx(1.0 / 6.0));
}

TEST_CASE("a triangle, one generator anywhere", "[cells]") {
  World w({{0, 0}, {1, 0}, {0, 1}}, {});
  VoronoiPartition part(w.cells, {{5, 5}});  // a generator far outside Ω
  const CellSummary s = part.summary(0);
  CHECK(s.mass == Approx(0.5));
  CHECK(s.centroid.x == Approx(1.0 / 3.0));
  CHECK(s.centroid.y == Approx(1.0 / 3.0));
  // Cost about the generator (5, 5): ½(∫|x - c|² + |c - g|² M), with ∫|x - c|² = 1/18.
  const double d2 = 2 * (5 - 1.0 / 3.0) * (5 - 1.0 / 3.0);
  CHECK(s.cost == Approx(0.5 * (1.0 / 18.0 + d2 * 0.5)));
  const std::vector<Vec2> at_centroid{{1.0 / 3.0, 1.0 / 3.0}};
  CHECK(part.cost(at_centroid) == Approx(1.0 / 36.0));
}

TEST_CASE("an L-shape: the centroid lies outside the cell's region", "[cells]") {
  World w({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {});
  VoronoiPartition part(w.cells, {{0.5, 0.5}});
  const CellSummary s = part.summary(0);
  CHECK(s.mass == Approx(3.0));
  CHECK(s.centroid.x == Approx(5.0 / 6.0));
  CHECK(s.centroid.y == Approx(5.0 / 6.0));
}

TEST_CASE("a ring around a hole, with the generator in the hole", "[cells]") {
  World w(square(-2, -2, 2, 2), {square(-1, -1, 1, 1)});
  VoronoiPartition one(w.cells, {{0, 0}});
  // ∫|x|² over [-a, a]² is 8a⁴/3: (128 - 8) / 3 = 40, cost 20.
  check_summary(one.summary(0), 12.0, {0, 0}, 20.0);
  VoronoiPartition two(w.cells, {{-1.5, 0}, {1.5, 0}});
  // Each half has area 6 and ∫x = 8 - 1 = 7.
  CHECK(two.summary(0).mass == Approx(6.0));
  CHECK(two.summary(1).centroid.x == Approx(7.0 / 6.0));
  CHECK(two.summary(0).centroid.x == Approx(-7.0 / 6.0));
  CHECK(two.summary(1).centroid.y == Approx(0.0).margin(1e-12));
}

TEST_CASE("a cell cut into two pieces by a hole", "[cells]") {
  World w(square(0, 0, 3, 3), {square(1, 0.5, 2, 2.5)});
  // The middle generator's cell is the box [0.15, 2.85] x [0.85, 2.15]; the hole cuts it
  // into [0.15, 1] x [0.85, 2.15] and [2, 2.85] x [0.85, 2.15].
  VoronoiPartition part(w.cells, {{1.5, 1.5}, {1.5, 2.8}, {1.5, 0.2}, {-1.2, 1.5}, {4.2, 1.5}});
  int pieces = 0;
  w.cells.for_each_piece({part.cell(0).begin(), part.cell(0).end()},
                         [&](const ConvexPolygon&) { ++pieces; });
  CHECK(pieces >= 2);
  const CellSummary s = part.summary(0);
  CHECK(s.mass == Approx(2 * 0.85 * 1.3));
  CHECK(s.centroid.x == Approx(1.5));
  CHECK(s.centroid.y == Approx(1.5));
  CHECK_FALSE(w.env.contains(s.centroid));  // the centroid lies in the hole
}

TEST_CASE("a cell that misses Ω has zero mass and stays put", "[cells]") {
  World w(square(0, 0, 1, 1), {});
  VoronoiPartition part(w.cells, {{0.5, 0.5}, {50, 50}});
  const CellSummary far = part.summary(1);
  CHECK(far.mass == 0.0);
  CHECK(far.centroid == Vec2{50, 50});
  CHECK(far.cost == 0.0);
  CHECK(part.summary(0).mass == Approx(1.0));
}

TEST_CASE("coincident generators are an error naming both", "[cells]") {
  World w(square(0, 0, 1, 1), {});
  try {
    VoronoiPartition part(w.cells, {{0.2, 0.2}, {0.7, 0.7}, {0.2, 0.2}});
    FAIL("coincident generators accepted");
  } catch (const GeometryError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("generators 0 and 2 coincide"));
  }
  CHECK_THROWS_AS(VoronoiPartition(w.cells, {{NAN, 0.2}}), GeometryError);
}

TEST_CASE("invariants on random generators in a cluttered environment", "[cells]") {
  World w(square(0, 0, 10, 8), {square(1, 1, 2, 3),
                                square(4, 4, 6, 5),
                                {{7, 1}, {9, 2}, {8, 3}},
                                square(2, 5, 3, 7),
                                {{5, 1}, {6, 1}, {6, 2.5}, {5.5, 1.5}, {5, 2.5}}});
  RandomStream rng(11, 0, "cells-test");
  for (int trial = 0; trial < 5; ++trial) {
    const int n = 5 + 20 * trial;
    std::vector<Vec2> gens;
    for (int i = 0; i < n; ++i)
      gens.push_back({rng.uniform(-1, 11), rng.uniform(-1, 9)});  // some outside Ω
    VoronoiPartition part(w.cells, gens);
    double total = 0;
    for (std::size_t i = 0; i < part.size(); ++i) {
      const CellSummary s = part.summary(i);
      total += s.mass;
      CHECK(s.mass >= 0.0);
      CHECK(s.cost >= 0.0);
      // The cell from all other generators as neighbours is the same cell.
      std::vector<Vec2> others;
      for (std::size_t j = 0; j < gens.size(); ++j) {
        if (j != i) others.push_back(gens[j]);
      }
      ConvexPolygon brute;
      w.cells.cell(gens[i], others, brute);
      const Moments m = w.cells.integrate(brute, gens[i]);
      CHECK(m.mass == Approx(s.mass).epsilon(1e-9).margin(1e-12));
      CHECK(0.5 * m.second == Approx(s.cost).epsilon(1e-9).margin(1e-12));
      // A cell lying wholly in Ω is convex: its centroid lies inside it.
      const auto cell = part.cell(i);
      bool in_free_space = cell.size() >= 3;
      for (Vec2 v : cell)
        in_free_space = in_free_space && w.env.contains(v);
      if (in_free_space && w.env.contains(s.centroid) && s.mass > 0) {
        for (std::size_t k = 0; k < cell.size(); ++k) {
          CHECK(cross(cell[(k + 1) % cell.size()] - cell[k], s.centroid - cell[k]) >= -1e-12);
        }
      }
    }
    CHECK(total == Approx(w.env.area()).epsilon(1e-12));
    CHECK(total == Approx(w.cells.total_mass()).epsilon(1e-12));
  }
}

TEST_CASE("cells do not overlap: pieces of different cells share no area", "[cells]") {
  World w(square(0, 0, 4, 4), {square(1, 1, 2, 2.5)});
  RandomStream rng(3, 0, "overlap");
  std::vector<Vec2> gens;
  for (int i = 0; i < 12; ++i)
    gens.push_back({rng.uniform(0, 4), rng.uniform(0, 4)});
  VoronoiPartition part(w.cells, gens);
  // Sample points: each point of Ω lies in exactly one cell (up to the boundaries), the
  // one of its nearest generator.
  for (int k = 0; k < 2000; ++k) {
    const Vec2 x{rng.uniform(0, 4), rng.uniform(0, 4)};
    if (!w.env.contains(x)) continue;
    int owners = 0;
    for (std::size_t i = 0; i < part.size(); ++i) {
      const auto c = part.cell(i);
      bool in = c.size() >= 3;
      for (std::size_t e = 0; e < c.size() && in; ++e)
        in = cross(c[(e + 1) % c.size()] - c[e], x - c[e]) > 1e-12;
      owners += in;
    }
    CHECK(owners <= 1);
  }
}

TEST_CASE("coincident generators split their cell into wedges, in index order", "[cells]") {
  World w(square(0, 0, 2, 2), {});
  const Vec2 c{1, 1};
  const auto split = VoronoiPartition::Coincident::split;
  // Two at the centre: the first takes the upper half, the second the lower; cost ½∫|x - c|²
  // over [0, 2] x [1, 2] = ½ (2/3 + 2/3).
  const VoronoiPartition two(w.cells, {c, c}, split);
  check_summary(two.summary(0), 2.0, {1, 1.5}, 2.0 / 3.0);
  check_summary(two.summary(1), 2.0, {1, 0.5}, 2.0 / 3.0);
  // Four at the centre: the quadrants, counter-clockwise from the x axis.
  const VoronoiPartition four(w.cells, {c, c, c, c}, split);
  const Vec2 quadrant[] = {{1.5, 1.5}, {0.5, 1.5}, {0.5, 0.5}, {1.5, 0.5}};
  for (std::size_t i = 0; i < 4; ++i)
    check_summary(four.summary(i), 1.0, quadrant[i], 1.0 / 3.0);
  // Three, beside a distinct fourth: the wedges tile the shared cell and have distinct
  // centroids; the masses add up to Ω's.
  const std::vector<Vec2> g{{0.7, 0.8}, {1.6, 1.2}, {0.7, 0.8}, {0.7, 0.8}};
  const VoronoiPartition three(w.cells, g, split);
  double mass = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i)
    mass += three.summary(i).mass;
  CHECK(mass == Approx(4.0).epsilon(1e-12));
  CHECK(three.summary(0).centroid != three.summary(2).centroid);
  CHECK(three.summary(2).centroid != three.summary(3).centroid);
  CHECK(three.summary(0).centroid != three.summary(3).centroid);
  // One robot's own cell, from the generators it knows, is the partition's cell.
  for (std::size_t i = 0; i < g.size(); ++i) {
    ConvexPolygon own;
    voronoi_cell(w.cells, g, i, own);
    const auto cell = three.cell(i);
    CHECK(std::vector<Vec2>(cell.begin(), cell.end()) == own);
  }
}

TEST_CASE("a partition clips only the cells asked for, the same in any order", "[cells]") {
  World w(square(0, 0, 10, 10), {square(4, 4, 6, 6)});
  RandomStream rng(5, 0, "lazy-cells");
  std::vector<Vec2> gens;
  for (int i = 0; i < 200; ++i)
    gens.push_back({rng.uniform(0, 10), rng.uniform(0, 10)});
  const VoronoiPartition forward(w.cells, gens);
  const VoronoiPartition backward(w.cells, gens);
  CHECK(forward.cells_computed() == 0);
  const CellSummary one = forward.summary(17);
  CHECK(forward.cells_computed() == 1);
  CHECK(forward.summary(17).centroid == one.centroid);  // kept, not clipped again
  CHECK(forward.cells_computed() == 1);
  for (std::size_t i = backward.size(); i-- > 0;)
    (void)backward.cell(i);
  CHECK(backward.cells_computed() == 200);
  CHECK(forward.cost() == backward.cost());  // every cell, bit for bit
  CHECK(forward.cells_computed() == 200);
  for (std::size_t i = 0; i < gens.size(); ++i) {
    const auto a = forward.cell(i), b = backward.cell(i);
    REQUIRE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
  }
}

TEST_CASE("a partition keeps the previous one's cells whose inputs are unchanged, bit for bit",
          "[cells]") {
  World w(square(0, 0, 10, 10), {square(4, 4, 6, 6)});
  RandomStream rng(19, 0, "kept-cells-test");
  std::vector<Vec2> gens;
  for (int i = 0; i < 200; ++i)
    gens.push_back({rng.uniform(0, 10), rng.uniform(0, 10)});
  gens[7] = gens[3];  // two coincident generators, split into wedges
  const auto same_cells = [](const VoronoiPartition& a, const VoronoiPartition& b) {
    bool same = a.size() == b.size();
    for (std::size_t i = 0; same && i < a.size(); ++i) {
      const auto ca = a.cell(i), cb = b.cell(i);
      same = std::equal(ca.begin(), ca.end(), cb.begin(), cb.end()) &&
             a.moments(i).mass == b.moments(i).mass &&
             a.summary(i).centroid == b.summary(i).centroid &&
             a.summary(i).cost == b.summary(i).cost;
    }
    return same;
  };
  const auto split = VoronoiPartition::Coincident::split;
  const VoronoiPartition before(w.cells, gens, split);
  (void)before.cost();  // every cell computed
  for (std::size_t moved : {0, 3, 150}) {
    std::vector<Vec2> next = gens;
    next[moved] += Vec2{0.05, -0.03};
    const VoronoiPartition kept(w.cells, next, split, VoronoiPartition(before));
    const VoronoiPartition fresh(w.cells, next, split);
    CHECK(same_cells(kept, fresh));
    // Only the moved generator's cell and those of its neighbours, before and after, are
    // clipped again: a few, not 200.
    INFO("moved " << moved << ", clipped " << kept.cells_computed());
    CHECK(kept.cells_computed() >= 1);
    CHECK(kept.cells_computed() <= 25);
    CHECK(fresh.cells_computed() == 200);
  }
  // Unchanged generators keep every cell; nothing is kept from another integrator, or from
  // a partition with another number of generators.
  const VoronoiPartition same(w.cells, gens, split, VoronoiPartition(before));
  (void)same.cost();
  CHECK(same.cells_computed() == 0);
  CHECK(same_cells(same, before));
  const World other(square(0, 0, 10, 10), {square(4, 4, 6, 6)});
  const VoronoiPartition elsewhere(other.cells, gens, split, VoronoiPartition(before));
  (void)elsewhere.cost();
  CHECK(elsewhere.cells_computed() == 200);
  std::vector<Vec2> fewer(gens.begin(), gens.end() - 1);
  const VoronoiPartition smaller(w.cells, fewer, split, VoronoiPartition(before));
  (void)smaller.cost();
  CHECK(smaller.cells_computed() == 199);
}
