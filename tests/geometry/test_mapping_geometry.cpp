// What a mapping robot learns from its readings (geometry/scan.hpp, known_lattice.hpp,
// map_elements.hpp): the free area a reading shows is what is visible from where it was
// taken, never inside an obstacle; obstacles become known once every wall has been seen; the
// believed Ω always contains Ω.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "core/random_stream.hpp"
#include "geometry/known_lattice.hpp"
#include "geometry/map_elements.hpp"
#include "geometry/scan.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

namespace {

// A room with a notch from the top (a pocket of the outer ring) and two holes.
Environment notched_room() {
  return Environment({{0, 0}, {4, 0}, {4, 3}, {2.5, 3}, {2.5, 2}, {1.5, 2}, {1.5, 3}, {0, 3}},
                     {square(0.5, 0.5, 1.0, 1.2), square(2.8, 0.6, 3.5, 1.0)});
}

// Cells a reading from o within range sees, by lines of sight to their centres: `clear`
// those whose line of sight keeps a margin from every wall (inside the reading's fan, not on
// its edges), else those with a line of sight at all.
bool sees(const Environment& env, Vec2 o, Vec2 c, double range, bool clear) {
  if (!env.locate(c) || distance(o, c) > range) return false;
  return clear ? env.clear_of_boundary(o, c, 1e-6) && env.boundary_distance(c) > 1e-6
               : env.segment_inside(o, c);
}

}  // namespace

TEST_CASE("a reading's fan marks what is visible from its origin and nothing else",
          "[geometry][mapping]") {
  const Environment env = notched_room();
  for (const double range : {double{INFINITY}, 1.0, 2.5}) {
    for (const Vec2 o : {Vec2{0.2, 0.2}, Vec2{2.0, 1.0}, Vec2{3.8, 2.8}, Vec2{1.2, 2.5}}) {
      INFO("range " << range << " from (" << o.x << ", " << o.y << ")");
      const Scan s = take_scan(env, o, range);
      KnownLattice l(env.bounds(), 160);
      l.fill(s.fan);
      // The chords leave out a sliver of the range circle (cos(π / 64) of the range).
      const double sure = std::isinf(range) ? range : range * std::cos(std::numbers::pi / 64);
      std::size_t marked = 0;
      for (std::int32_t j = 0; j < l.ny(); ++j) {
        for (std::int32_t i = 0; i < l.nx(); ++i) {
          const Vec2 c = l.centre(i, j);
          if (l.at(i, j)) {
            ++marked;
            CHECK(sees(env, o, c, range * (1 + 1e-12), false));
          } else {
            CHECK_FALSE(sees(env, o, c, sure, true));
          }
        }
      }
      CHECK(marked > 100);
    }
  }
}

TEST_CASE("a reading from the boundary marks nothing inside the wall it stands on",
          "[geometry][mapping]") {
  const Environment env = notched_room();
  for (const Vec2 o : {Vec2{2.0, 2.0}, Vec2{0.0, 1.5}, Vec2{0.75, 0.5}, Vec2{1.5, 2.0}}) {
    for (const double range : {double{INFINITY}, 0.8}) {
      const Scan s = take_scan(env, o, range);
      KnownLattice l(env.bounds(), 160);
      l.fill(s.fan);
      CHECK(l.count() > 0);
      const KnownLattice free = KnownLattice::of_free_space(env, 160);
      CHECK(l.common(free) == l.count());  // every marked cell's centre is in Ω
    }
  }
}

TEST_CASE("a reading split to fit messages marks what the whole reading does",
          "[geometry][mapping]") {
  const Environment env = notched_room();
  const Scan whole = take_scan(env, {2.0, 1.0}, INFINITY);
  REQUIRE(whole.pieces.size() > 6);
  const std::uint32_t limit = 8 + 2 + 3 * 20;  // three pieces a part
  const std::vector<Scan> parts = split_scan(env, whole, limit);
  CHECK(parts.size() == (whole.pieces.size() + 2) / 3);
  std::size_t pieces = 0;
  KnownLattice a(env.bounds(), 200), b(env.bounds(), 200);
  a.fill(whole.fan);
  for (const Scan& p : parts) {
    CHECK(p.bytes() <= limit);
    pieces += p.pieces.size();
    b.fill(p.fan);
  }
  CHECK(pieces == whole.pieces.size());
  // The parts tile the whole fan; only cells on their shared rays may differ.
  const double common = static_cast<double>(a.common(b));
  CHECK(common >= 0.995 * static_cast<double>(a.count()));
  CHECK(common >= 0.995 * static_cast<double>(b.count()));
  CHECK(split_scan(env, whole, whole.bytes()).size() == 1);
}

TEST_CASE("obstacles are the holes and, without the outer ring, its pockets",
          "[geometry][mapping]") {
  const Environment env = notched_room();
  const std::vector<MapElement> holes = map_elements(env, false);
  REQUIRE(holes.size() == 2);
  const std::vector<MapElement> all = map_elements(env, true);
  REQUIRE(all.size() == 3);
  const MapElement& pocket = all[2];
  CHECK(pocket.ring == 0);
  CHECK(pocket.edges.size() == 3);  // the notch's three walls
  const double box = 4.0 * 3.0, notch = 1.0 * 1.0, h0 = 0.5 * 0.7, h1 = 0.7 * 0.4;
  REQUIRE(env.area() == Approx(box - notch - h0 - h1));
  // The believed Ω, for each set of known obstacles: the box less what is known.
  for (int mask = 0; mask < 8; ++mask) {
    const std::vector<bool> known{(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
    const auto belief = believed_environment(env, all, known);
    const double expected =
        box - (known[0] ? h0 : 0) - (known[1] ? h1 : 0) - (known[2] ? notch : 0);
    INFO("mask " << mask);
    CHECK(belief->area() == Approx(expected).epsilon(1e-12));
    for (const auto& ring : env.rings())
      for (const Vec2 v : ring)
        CHECK(belief->locate(v));  // Ω̂ ⊇ Ω
  }
  // With the outer ring known, only holes: the prior is Ω's outer ring.
  const auto outer = believed_environment(env, holes, {false, false});
  CHECK(outer->area() == Approx(box - notch).epsilon(1e-12));
}

TEST_CASE("pockets at corners and on several sides open to the box round them",
          "[geometry][mapping]") {
  // A cut corner (one diagonal wall) and a notch from the left side.
  const Environment env(
      {{0, 0}, {3, 0}, {3, 1.5}, {2, 2}, {0, 2}, {0, 1.2}, {0.8, 1.2}, {0.8, 0.8}, {0, 0.8}}, {});
  const std::vector<MapElement> all = map_elements(env, true);
  REQUIRE(all.size() == 2);
  const double box = 3 * 2, corner = 0.5 * 1 * 0.5, notch = 0.8 * 0.4;
  REQUIRE(env.area() == Approx(box - corner - notch));
  CHECK(believed_environment(env, all, {false, false})->area() == Approx(box));
  CHECK(believed_environment(env, all, {true, true})->area() == Approx(env.area()));
  const double one = believed_environment(env, all, {true, false})->area();
  const double other = believed_environment(env, all, {false, true})->area();
  CHECK(std::min(one, other) == Approx(box - std::max(corner, notch)));
  CHECK(std::max(one, other) == Approx(box - std::min(corner, notch)));
}

TEST_CASE("an obstacle is known once every wall of it has been seen", "[geometry][mapping]") {
  const Environment env = notched_room();
  const std::vector<MapElement> all = map_elements(env, true);
  SeenWalls seen(env);
  // From below the first hole: its lower wall only.
  seen.add(take_scan(env, {0.75, 0.2}, INFINITY));
  CHECK_FALSE(seen.seen(all[0]));
  // Round it: every wall.
  for (const Vec2 o : {Vec2{0.2, 0.85}, Vec2{1.3, 0.85}, Vec2{0.75, 1.5}})
    seen.add(take_scan(env, o, INFINITY));
  CHECK(seen.seen(all[0]));
  // A short range sees a long wall in parts; together they cover it.
  SeenWalls parts(env);
  const std::uint32_t bottom = 0;  // the outer ring's first wall, (0, 0) to (4, 0)
  for (double x = 0.3; x < 4.0; x += 0.5) {
    CHECK_FALSE(parts.seen(bottom));
    parts.add(take_scan(env, {x, 0.3}, 0.6));
  }
  CHECK(parts.seen(bottom));
}

TEST_CASE("a reading from a wall's corner marks the side it sees, to the last rounding",
          "[geometry][mapping]") {
  // A maze wall whose corner (0.4, 4) the visibility's clipping does not reproduce exactly
  // (0.4 + 1.0 · (16.5 − 0.4) rounds to 0.3999999999999986 on the way back).
  const Environment env(square(0, 0, 20, 20), {square(0.4, 4, 16.5, 4.2)});
  for (const Vec2 o : {Vec2{0.4, 4}, Vec2{0.4, 4 - 1e-12}, Vec2{16.5, 4.2}, Vec2{3.0, 4.0},
                       Vec2{0.4 - 1e-13, 4.1}}) {
    for (const double range : {1.0, 2.5, double{INFINITY}}) {
      INFO("from (" << o.x << ", " << o.y << "), range " << range);
      const Scan s = take_scan(env, o, range);
      KnownLattice l(Box{o - Vec2{2, 2}, o + Vec2{2, 2}}, 400);  // 1 cm cells round it
      l.fill(s.fan);
      const double sure = std::isinf(range) ? range : range * std::cos(std::numbers::pi / 64);
      std::size_t clear = 0;
      for (std::int32_t j = 0; j < l.ny(); ++j) {
        for (std::int32_t i = 0; i < l.nx(); ++i) {
          const Vec2 c = l.centre(i, j);
          if (!env.locate(c) || distance(o, c) < 1e-3) continue;
          // From a point just along the line of sight: the corner itself touches the walls.
          const Vec2 from = o + (1e-4 / distance(o, c)) * (c - o);
          const bool visible = env.segment_inside(o, c);
          if (l.at(i, j)) CHECK(visible);
          if (distance(o, c) <= sure && env.clear_of_boundary(from, c, 1e-6)) {
            ++clear;
            CHECK(l.at(i, j));
          }
        }
      }
      CHECK(clear > 1000);
      // Nothing inside the wall.
      for (std::int32_t j = 0; j < l.ny(); ++j)
        for (std::int32_t i = 0; i < l.nx(); ++i)
          if (l.at(i, j)) CHECK(env.locate(l.centre(i, j)));
    }
  }
}

TEST_CASE("marking runs sets the cells they name, across words, and counts the new ones",
          "[geometry][mapping]") {
  KnownLattice a(Box{{0, 0}, {1, 0.7}}, 150), b(Box{{0, 0}, {1, 0.7}}, 150);
  RandomStream rng(7, 0, "runs");
  for (int round = 0; round < 200; ++round) {
    std::vector<LatticeRun> runs;
    for (int k = 0; k < 5; ++k) {
      const auto j = static_cast<std::int32_t>(rng.uniform(0, a.ny() - 1e-9));
      const auto i0 = static_cast<std::int32_t>(rng.uniform(0, a.nx() - 1e-9));
      const auto i1 =
          std::min<std::int32_t>(a.nx() - 1, i0 + static_cast<std::int32_t>(rng.uniform(0, 140)));
      runs.push_back({j, i0, i1});
    }
    std::vector<std::size_t> fresh;
    const std::uint64_t before = a.count();
    const std::uint64_t added = a.mark(runs, &fresh);
    CHECK(a.count() == before + added);
    CHECK(fresh.size() == added);
    std::uint64_t set_one_by_one = 0;
    for (const LatticeRun& r : runs)
      for (std::int32_t i = r.i0; i <= r.i1; ++i)
        if (!b.at(i, r.j)) {
          b.set(i, r.j);
          ++set_one_by_one;
        }
    CHECK(added == set_one_by_one);
    for (const std::size_t k : fresh) {
      const auto i = static_cast<std::int32_t>(k % static_cast<std::size_t>(a.nx()));
      const auto j = static_cast<std::int32_t>(k / static_cast<std::size_t>(a.nx()));
      CHECK(a.at(i, j));
    }
  }
  CHECK(a.common(b) == b.count());
  CHECK(a.count() == b.count());
}

TEST_CASE("outer rings that touch their box at single vertices open to it", "[geometry][mapping]") {
  // A diamond touches its box at four vertices: four corner pockets.
  const Environment diamond({{1, 0}, {2, 1}, {1, 2}, {0, 1}}, {});
  const auto d = map_elements(diamond, true);
  REQUIRE(d.size() == 4);
  CHECK(believed_environment(diamond, d, {false, false, false, false})->area() == Approx(4.0));
  CHECK(believed_environment(diamond, d, {true, false, true, false})->area() == Approx(3.0));
  CHECK(believed_environment(diamond, d, {true, true, true, true})->area() == Approx(2.0));
  // A spike: a ring that meets its box's top side at one vertex, between two pockets.
  const Environment spike({{0, 0}, {4, 0}, {4, 2}, {2, 1}, {1.5, 3}, {1, 1}, {0, 2}}, {});
  const auto s = map_elements(spike, true);
  REQUIRE(s.size() == 2);
  const double box = 4 * 3;
  CHECK(believed_environment(spike, s, {false, false})->area() == Approx(box));
  CHECK(believed_environment(spike, s, {true, true})->area() == Approx(spike.area()));
  const double one = believed_environment(spike, s, {true, false})->area();
  const double other = believed_environment(spike, s, {false, true})->area();
  CHECK(one + other == Approx(box + spike.area()));  // the two pockets tile box \ Ω
}
