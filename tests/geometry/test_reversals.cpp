// Reversals (geometry/reversals): a path that walks back over its own ground, and the
// paths that only pass beside it.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "geometry/reversals.hpp"

using namespace covsim;

namespace {
// Straight from a to b in steps of at most `step`.
void walk(std::vector<Vec2>& path, Vec2 b, double step) {
  const Vec2 a = path.back();
  const double d = distance(a, b);
  const int n = static_cast<int>(std::ceil(d / step - 1e-12));
  for (int k = 1; k <= n; ++k)
    path.push_back(a + (static_cast<double>(k) / n) * (b - a));
}
}  // namespace

TEST_CASE("reversals: a wall walked back and forth turns back at each end", "[reversals]") {
  // The notch's bottom of the paper's U, walked right, back left and right again in 1 cm
  // steps, reaching each corner with a short step.
  std::vector<Vec2> path{{0.35, 0.35}};
  walk(path, {0.6453, 0.35}, 0.01);
  walk(path, {0.37, 0.35}, 0.01);
  walk(path, {0.65, 0.35}, 0.01);
  const std::vector<std::size_t> r = reversals(path, 0.002, 1e-9);
  REQUIRE(r.size() == 2);
  CHECK(path[r[0]].x == Approx(0.6453));
  CHECK(path[r[1]].x == Approx(0.37));
  // Turning back after a single step counts too, when that step is at least min_length.
  const std::vector<Vec2> once{{0, 0}, {0.01, 0}, {0, 0}, {0, 1}};
  CHECK(reversals(once, 0.002, 1e-9).size() == 1);
  CHECK(reversals(once, 0.02, 1e-9).empty());  // a hundredth is less than that
}

TEST_CASE("reversals: passing beside earlier ground is no reversal", "[reversals]") {
  // Round a 3 cm thick wall's end: along one face, across its end, back along the other.
  std::vector<Vec2> round{{0, 0}};
  walk(round, {1, 0}, 0.05);
  walk(round, {1, 0.03}, 0.05);
  walk(round, {0, 0.03}, 0.05);
  CHECK(reversals(round, 0.01, 1e-6).empty());
  // Down one face of a slot 2 cm wide and up the other, cutting straight across its bottom.
  const std::vector<Vec2> slot{{0, 1}, {0, 0.5}, {0, 0}, {0.02, 0.5}, {0.02, 1}};
  CHECK(reversals(slot, 0.01, 1e-6).empty());
  // A sharp turn that is not back along the way it came.
  const std::vector<Vec2> turn{{0, 0}, {1, 0}, {0.2, 0.3}};
  CHECK(reversals(turn, 0.01, 1e-6).empty());
  // A zigzag of 7 mm (range noise) is no reversal at a min_length of 1 cm; at 5 mm both of
  // its turns are, the second back over the first's ground.
  const std::vector<Vec2> zig{{0, 0}, {0.05, 0}, {0.10, 0}, {0.093, 0.0005}, {0.14, 0.001}};
  CHECK(reversals(zig, 0.01, 0.002).empty());
  CHECK(reversals(zig, 0.005, 0.002).size() == 2);
}

TEST_CASE("reversals: a stop on the way is no turn, and a path too short has none", "[reversals]") {
  // Standing still (repeated positions) between the two ways of a reversal.
  const std::vector<Vec2> wait{{0, 0}, {0.5, 0}, {0.5, 0}, {0.5, 0}, {0.2, 0}};
  const std::vector<std::size_t> r = reversals(wait, 0.01, 1e-9);
  REQUIRE(r.size() == 1);
  CHECK(wait[r[0]] == Vec2{0.5, 0});
  CHECK(reversals({}, 0.01, 1e-9).empty());
  CHECK(reversals({{1, 1}}, 0.01, 1e-9).empty());
  CHECK(reversals({{0, 0}, {1, 0}}, 0.01, 1e-9).empty());
}
