// What a robot that maps on an occupancy grid learns (geometry/grid_patch.hpp,
// log_odds_grid.hpp, cell_region.hpp): a reading's hits lie on the walls it saw and its misses
// in the area it showed free; log-odds add and clamp; the cells joined to the robots become
// an environment whose area is theirs, outline corners only, never touching itself.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <tuple>

#include "core/random_stream.hpp"
#include "geometry/cell_region.hpp"
#include "geometry/grid_patch.hpp"
#include "geometry/log_odds_grid.hpp"
#include "geometry/scan.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

namespace {

Environment room_with_holes() {
  return Environment({{0, 0}, {4, 0}, {4, 3}, {2.5, 3}, {2.5, 2}, {1.5, 2}, {1.5, 3}, {0, 3}},
                     {square(0.5, 0.5, 1.0, 1.2), square(2.8, 0.6, 3.5, 1.0)});
}

std::size_t count(const std::vector<std::uint8_t>& v) {
  std::size_t n = 0;
  for (const std::uint8_t x : v)
    n += x != 0 ? 1 : 0;
  return n;
}

std::set<std::tuple<int, int>> cells_of(const std::vector<LatticeRun>& runs) {
  std::set<std::tuple<int, int>> out;
  for (const LatticeRun& r : runs)
    for (int i = r.i0; i <= r.i1; ++i)
      out.insert({i, r.j});
  return out;
}

}  // namespace

TEST_CASE("a reading's hits lie on the walls it saw, its misses where it showed free space",
          "[geometry][mapping]") {
  const Environment env = room_with_holes();
  const KnownLattice grid(env.bounds(), 80);
  const double reach = grid.cell() * std::sqrt(0.5);  // from a cell's centre to its corners
  for (const Vec2 o : {Vec2{0.3, 0.3}, Vec2{2.0, 1.0}, Vec2{3.7, 2.8}, Vec2{1.2, 0.85}}) {
    for (const double range : {0.8, double{INFINITY}}) {
      INFO(o.x << ", " << o.y << ", range " << range);
      const Scan scan = take_scan(env, o, range);
      const GridPatch patch = inverse_sensor_model(grid, scan);
      const auto hits = cells_of(patch.hits), misses = cells_of(patch.misses);
      CHECK(!hits.empty());
      CHECK(!misses.empty());
      for (const auto& [i, j] : hits) {
        // A hit's square meets a wall.
        CHECK(env.boundary_distance(grid.centre(i, j)) <= reach * (1.0 + 1e-9));
        CHECK(misses.count({i, j}) == 0);
      }
      for (const auto& [i, j] : misses) {
        // A miss's centre lies in Ω, within range, and no wall crosses its square.
        CHECK(env.contains(grid.centre(i, j)));
        CHECK(distance(grid.centre(i, j), o) <= range);
        CHECK(env.boundary_distance(grid.centre(i, j)) > grid.cell() * 0.5 - 1e-12);
      }
      // Cut to fit messages, the parts hold the same cells.
      const std::vector<GridPatch> parts = split_patch(patch, 100);
      std::set<std::tuple<int, int>> hit_parts, miss_parts;
      for (const GridPatch& p : parts) {
        CHECK(p.bytes() <= 100);
        for (const auto& c : cells_of(p.hits))
          hit_parts.insert(c);
        for (const auto& c : cells_of(p.misses))
          miss_parts.insert(c);
      }
      CHECK(hit_parts == hits);
      CHECK(miss_parts == misses);
    }
  }
}

TEST_CASE("range noise moves each measured wall point once, along its ray", "[geometry][mapping]") {
  const Environment env = room_with_holes();
  const Vec2 o{2.0, 1.0};
  const Scan exact = take_scan(env, o, INFINITY);
  Scan noisy = exact;
  RandomStream rng(7, 0, "noise");
  add_range_noise(noisy, rng, 0.05, env.tolerance());
  REQUIRE(noisy.pieces.size() == exact.pieces.size());
  bool moved = false;
  for (std::size_t k = 0; k < exact.pieces.size(); ++k) {
    const VisiblePiece &a = exact.pieces[k], &b = noisy.pieces[k];
    // Along the ray from the origin.
    CHECK(std::abs(cross(a.a - o, b.a - o)) <= 1e-9);
    CHECK(std::abs(cross(a.b - o, b.b - o)) <= 1e-9);
    moved = moved || distance(a.a, b.a) > 1e-6;
    // Joined pieces stay joined.
    const std::size_t next = (k + 1) % exact.pieces.size();
    if (exact.pieces[k].b == exact.pieces[next].a) CHECK(b.b == noisy.pieces[next].a);
  }
  CHECK(moved);
  // The fan goes through the noisy points.
  std::size_t through = 0;
  for (const Vec2 v : noisy.fan)
    for (const VisiblePiece& p : noisy.pieces)
      through += v == p.a || v == p.b ? 1 : 0;
  CHECK(through > 0);
  Scan shifted = noisy;
  shift(shifted, {0.1, -0.2});
  CHECK(shifted.origin == noisy.origin + Vec2{0.1, -0.2});
  CHECK(shifted.fan.back() == noisy.fan.back() + Vec2{0.1, -0.2});
  Scan same = exact;
  add_range_noise(same, rng, 0.0, env.tolerance());
  CHECK(same.fan == exact.fan);
}

TEST_CASE("log-odds add a reading's hits and misses, clamped", "[geometry][mapping]") {
  const KnownLattice lattice(Box{{0, 0}, {1, 1}}, 10);
  LogOddsGrid grid(lattice, 0.7, 0.4);
  const GridPatch hit{{LatticeRun{2, 3, 4}}, {}}, miss{{}, {LatticeRun{2, 4, 5}}};
  const std::size_t c = grid.grid().index(4, 2), other = grid.grid().index(5, 2);
  CHECK_FALSE(grid.observed(c));
  CHECK(grid.apply(hit) == 2);
  CHECK(grid.occupied(c));
  CHECK(grid.log_odds(c) == Approx(std::log(0.7 / 0.3)));
  const std::uint64_t v = grid.version();
  // One miss does not outvote a hit (0.85 - 0.41); three do.
  CHECK(grid.apply(miss) == 0);
  CHECK(grid.version() == v);
  CHECK(grid.occupied(c));
  CHECK_FALSE(grid.occupied(other));
  CHECK(grid.observed(other));
  grid.apply(miss);
  CHECK(grid.occupied(c));
  grid.apply(miss);
  CHECK_FALSE(grid.occupied(c));
  CHECK(grid.version() == v + 1);
  // Clamped: many hits, then as many misses as OctoMap's thresholds allow, flip the cell.
  for (int k = 0; k < 50; ++k)
    grid.apply(hit);
  CHECK(grid.log_odds(c) == Approx(std::log(0.971 / 0.029)));
  int misses = 0;
  while (grid.occupied(c)) {
    grid.apply(miss);
    ++misses;
  }
  CHECK(misses == 9);  // 3.50 / 0.405 rounded up
  CHECK_THROWS(LogOddsGrid(lattice, 0.4, 0.3));
}

TEST_CASE("the cells joined to the robots become an environment of their outline",
          "[geometry][mapping]") {
  const CellGrid g{{1.0, 2.0}, 0.25, 12, 10};
  std::vector<std::uint8_t> open(g.size(), 1);
  const auto close = [&](int i, int j) { open[g.index(i, j)] = 0; };
  // A closed block inside (a hole), a wall across the grid with a door, and a closed
  // pocket beyond the wall.
  for (int i = 3; i <= 5; ++i)
    for (int j = 3; j <= 4; ++j)
      close(i, j);
  for (int j = 0; j < 10; ++j)
    if (j != 7) close(8, j);
  SECTION("a hole and a door") {
    const std::vector<std::uint8_t> region = seeded_region(g, open, {Vec2{1.1, 2.1}});
    CHECK(count(region) == count(open));
    const auto env = region_environment(g, region);
    CHECK(env->hole_count() == 1);
    CHECK(env->area() == Approx(static_cast<double>(count(region)) * 0.0625).epsilon(1e-12));
    CHECK(env->contains({1.1, 2.1}));
    CHECK_FALSE(env->contains({1.0 + 4.5 * 0.25, 2.0 + 3.5 * 0.25}));  // in the block
    // Corners only: the outer ring of a box with a notched wall has few vertices.
    CHECK(env->outer().size() <= 12);
  }
  SECTION("a closed door leaves the far side out") {
    close(8, 7);
    const std::vector<std::uint8_t> region = seeded_region(g, open, {Vec2{1.1, 2.1}});
    CHECK(count(region) == 8 * 10 - 6);
    CHECK(region_environment(g, region)->area() == Approx(74 * 0.0625));
    // A seed on a closed cell starts from the nearest open one.
    close(9, 0);
    const std::vector<std::uint8_t> far =
        seeded_region(g, open, {Vec2{1.0 + 9.5 * 0.25, 2.0 + 0.5 * 0.25}});
    CHECK(count(far) == 3 * 10 - 1);
  }
  SECTION("cells that meet only at a corner are parted") {
    // Open cells (9, 4) and (10, 5) meet at a corner beside closed (10, 4) and (9, 5): left
    // alone, the outline would touch itself there.
    close(10, 4);
    close(9, 5);
    const std::vector<std::uint8_t> region = seeded_region(g, open, {Vec2{1.1, 2.1}});
    CHECK(count(region) == count(open) - 1);
    const auto env = region_environment(g, region);
    CHECK(env->area() == Approx(static_cast<double>(count(region)) * 0.0625));
  }
  SECTION("nothing open near the seed: no region") {
    const std::vector<std::uint8_t> closed(g.size(), 0);
    CHECK(count(seeded_region(g, closed, {Vec2{1.1, 2.1}})) == 0);
    CHECK_THROWS(region_environment(g, closed));
  }
}

TEST_CASE("a region of cells shrunk by a radius keeps the cells a body there clears",
          "[geometry][mapping]") {
  const CellGrid g{{1.0, 2.0}, 0.25, 12, 10};
  const std::vector<std::uint8_t> open(g.size(), 1);
  // The grid's edge is the outside: cells at least 0.3 m from it, square to square.
  const auto parts = eroded_parts(g, open, 0.3);
  REQUIRE(parts.size() == 1);
  CHECK(parts[0]->area() == Approx(8 * 6 * 0.0625));
  for (const Vec2 v : parts[0]->outer()) {
    CHECK(v.x - 1.0 >= 0.3);
    CHECK(1.0 + 12 * 0.25 - v.x >= 0.3);
  }
  // A closed wall across with a door one cell wide: no body of radius 0.2 passes it, so the
  // two rooms are two parts, the larger first; at 1 m nothing is left.
  std::vector<std::uint8_t> walled = open;
  for (int j = 0; j < 10; ++j)
    if (j != 5) walled[g.index(7, j)] = 0;
  const auto rooms = eroded_parts(g, walled, 0.2);
  REQUIRE(rooms.size() == 2);
  CHECK(rooms[0]->area() > rooms[1]->area());
  CHECK(eroded_parts(g, walled, 1.0).empty());
}
