#include <catch2/catch.hpp>

#include <cmath>

#include "core/random_stream.hpp"
#include "geometry/configuration_space.hpp"
#include "geometry/geometry_error.hpp"
#include "geometry/placement.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using Catch::Matchers::Contains;
using covsim::test::square;

namespace {

std::vector<Vec2> reversed(std::vector<Vec2> ring) {
  return {ring.rbegin(), ring.rend()};
}

}  // namespace

TEST_CASE("a radius of 0 is the environment itself", "[geometry][configuration_space]") {
  const Environment env(square(0, 0, 4, 4), {square(1.5, 1.5, 2.5, 2.5)});
  const ConfigurationSpace space(env, 0.0);
  CHECK(space.part_count() == 1);
  CHECK(&space.part(0) == &env);
  CHECK(space.part_of({0.0, 0.0}) == 0u);
  CHECK_FALSE(space.part_of({2.0, 2.0}));
  CHECK_FALSE(space.overlaps_boundary({0.0, 1.0}));
}

TEST_CASE("the walls move in by the radius and the obstacles grow by it",
          "[geometry][configuration_space]") {
  const Environment env(square(0, 0, 4, 4), {reversed(square(1.5, 1.5, 2.5, 2.5))});
  const ConfigurationSpace space(env, 0.25);
  REQUIRE(space.part_count() == 1);
  const Environment& free = space.part(0);
  // [0.25, 3.75]² less the hole [1.25, 2.75]²: mitered corners keep both square.
  CHECK(free.area() == Approx(3.5 * 3.5 - 1.5 * 1.5).epsilon(1e-12));
  CHECK(free.hole_count() == 1);
  CHECK(free.bounds().lo.x == Approx(0.25));
  CHECK(free.bounds().hi.y == Approx(3.75));
  CHECK(space.part_of({0.3, 0.3}) == 0u);
  CHECK_FALSE(space.part_of({0.2, 2.0}));  // its body would cross the outer wall
  CHECK_FALSE(space.part_of({1.3, 2.0}));  // or the obstacle
  CHECK(space.overlaps_boundary({0.2, 2.0}));
  CHECK(space.overlaps_boundary({1.3, 2.0}));
  CHECK_FALSE(space.overlaps_boundary({0.3, 2.0}));
  CHECK(space.overlaps_boundary({2.0, 2.0}));  // inside the obstacle
}

TEST_CASE("a passage narrower than the body closes and splits the space",
          "[geometry][configuration_space]") {
  // Gaps of 0.3 m above and below the obstacle.
  const Environment env(square(0, 0, 6, 2), {square(2, 0.3, 4, 1.7)});
  const ConfigurationSpace open(env, 0.1);
  CHECK(open.part_count() == 1);
  CHECK(open.part_of({1, 1}) == open.part_of({5, 1}));
  const ConfigurationSpace closed(env, 0.2);
  REQUIRE(closed.part_count() == 2);
  const auto left = closed.part_of({1, 1}), right = closed.part_of({5, 1});
  REQUIRE(left);
  REQUIRE(right);
  CHECK(*left != *right);
  // Each room: [0.2, 1.8] × [0.2, 1.8] (its side toward the obstacle pushed back to x = 1.8).
  CHECK(closed.part(*left).area() == Approx(1.6 * 1.6).epsilon(1e-12));
  CHECK(closed.part(*right).area() == Approx(1.6 * 1.6).epsilon(1e-12));
  CHECK_FALSE(closed.part_of({3, 0.15}));
}

TEST_CASE("a body too large for the environment is refused", "[geometry][configuration_space]") {
  const Environment env(square(0, 0, 2, 1), {});
  CHECK_THROWS_WITH(ConfigurationSpace(env, 0.5), Contains("fits nowhere"));
  CHECK_NOTHROW(ConfigurationSpace(env, 0.49));
  CHECK_THROWS_WITH(ConfigurationSpace(env, -0.1), Contains("radius"));
  CHECK_THROWS_WITH(ConfigurationSpace(env, NAN), Contains("radius"));
}

TEST_CASE(
    "every point of the shrunk space keeps the body off the walls, and it misses only "
    "the mitered corners",
    "[geometry][configuration_space]") {
  // Thin walls and rooms with right-angled corners only: a point at least r√2 from ∂Ω is
  // in the shrunk space (a miter reaches r√2 from the corner it turns round).
  const Environment env(
      square(0, 0, 6, 4),
      {square(1.9, 0.4, 2.1, 3.0), square(3.9, 1.0, 4.1, 4.0 - 0.3), square(0.8, 3.2, 1.2, 3.6)});
  const double r = 0.07;
  const ConfigurationSpace space(env, r);
  CHECK(space.part_count() == 1);
  RandomStream rng(7, 0, "test");
  int inside = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2 p = uniform_point(env, rng);
    const double d = env.boundary_distance(p);
    const bool in = space.part_of(p).has_value();
    if (in) {
      ++inside;
      CHECK(d >= r - 1e-9);
      CHECK_FALSE(space.overlaps_boundary(p));
    }
    if (d >= r * std::sqrt(2.0) + 1e-9) CHECK(in);
    if (d < r - 1e-9) CHECK(space.overlaps_boundary(p));
  }
  CHECK(inside > 15000);
}

TEST_CASE("an offset's sliver thinner than rounding is no part of the free space",
          "[geometry][configuration_space]") {
  // A robot's occupancy-grid belief of the U room (odometry, range 0.5 m, decentralized): at
  // 0.02 m the offset left a rectangle 1.1e-16 m wide, which Ω's constructor once took and
  // could not triangulate.
  const Environment belief({{0.95000000000000007, 0},
                            {1, 0},
                            {1, 0.014999999999999999},
                            {0.25, 0.014999999999999999},
                            {0.25, 0.02},
                            {0.68000000000000005, 0.02},
                            {0.68000000000000005, 0.025000000000000001},
                            {1, 0.025000000000000001},
                            {1, 0.77500000000000002},
                            {0.995, 0.77500000000000002},
                            {0.995, 0.79000000000000004},
                            {1, 0.79000000000000004},
                            {1, 0.94500000000000006},
                            {0.995, 0.94500000000000006},
                            {0.995, 0.96999999999999997},
                            {1, 0.96999999999999997},
                            {1, 1},
                            {0.65500000000000003, 1},
                            {0.65500000000000003, 0.98999999999999999},
                            {0.66000000000000003, 0.98999999999999999},
                            {0.66000000000000003, 0.98499999999999999},
                            {0.65500000000000003, 0.98499999999999999},
                            {0.65500000000000003, 0.97999999999999998},
                            {0.65000000000000002, 0.97999999999999998},
                            {0.65000000000000002, 0.76000000000000001},
                            {0.65500000000000003, 0.76000000000000001},
                            {0.65500000000000003, 0.71999999999999997},
                            {0.65000000000000002, 0.71999999999999997},
                            {0.65000000000000002, 0.41000000000000003},
                            {0.65500000000000003, 0.41000000000000003},
                            {0.65500000000000003, 0.375},
                            {0.67500000000000004, 0.375},
                            {0.67500000000000004, 0.37},
                            {0.69000000000000006, 0.37},
                            {0.69000000000000006, 0.69000000000000006},
                            {0.69500000000000006, 0.69000000000000006},
                            {0.69500000000000006, 0.36499999999999999},
                            {0.39000000000000001, 0.36499999999999999},
                            {0.39000000000000001, 0.37},
                            {0.38500000000000001, 0.37},
                            {0.38500000000000001, 0.80500000000000005},
                            {0.39000000000000001, 0.80500000000000005},
                            {0.39000000000000001, 0.92000000000000004},
                            {0.38500000000000001, 0.92000000000000004},
                            {0.38500000000000001, 0.95000000000000007},
                            {0.39000000000000001, 0.95000000000000007},
                            {0.39000000000000001, 1},
                            {0.36499999999999999, 1},
                            {0.36499999999999999, 0.94500000000000006},
                            {0.35999999999999999, 0.94500000000000006},
                            {0.35999999999999999, 0.91500000000000004},
                            {0.36499999999999999, 0.91500000000000004},
                            {0.36499999999999999, 0.85999999999999999},
                            {0.35999999999999999, 0.85999999999999999},
                            {0.35999999999999999, 0.68500000000000005},
                            {0.35499999999999998, 0.68500000000000005},
                            {0.35499999999999998, 0.70000000000000007},
                            {0.35000000000000003, 0.70000000000000007},
                            {0.35000000000000003, 0.995},
                            {0.32000000000000001, 0.995},
                            {0.32000000000000001, 0.35000000000000003},
                            {0.315, 0.35000000000000003},
                            {0.315, 1},
                            {0, 1},
                            {0, 0.28500000000000003},
                            {0.0050000000000000001, 0.28500000000000003},
                            {0.0050000000000000001, 0.245},
                            {0.01, 0.245},
                            {0.01, 0.17500000000000002},
                            {0.014999999999999999, 0.17500000000000002},
                            {0.014999999999999999, 0.30499999999999999},
                            {0.02, 0.30499999999999999},
                            {0.02, 0.68500000000000005},
                            {0.025000000000000001, 0.68500000000000005},
                            {0.025000000000000001, 0.01},
                            {0.76500000000000001, 0.01},
                            {0.76500000000000001, 0.0050000000000000001},
                            {0.95000000000000007, 0.0050000000000000001}},
                           {{{0.95999999999999996, 0.0050000000000000001},
                             {0.95999999999999996, 0.01},
                             {0.995, 0.01},
                             {0.995, 0.0050000000000000001}},
                            {{0.37, 0.35499999999999998},
                             {0.37, 0.65500000000000003},
                             {0.36499999999999999, 0.65500000000000003},
                             {0.36499999999999999, 0.66000000000000003},
                             {0.37, 0.66000000000000003},
                             {0.37, 0.71999999999999997},
                             {0.375, 0.71999999999999997},
                             {0.375, 0.35999999999999999},
                             {0.67500000000000004, 0.35999999999999999},
                             {0.67500000000000004, 0.35499999999999998}}});
  const ConfigurationSpace space(belief, 0.02);
  CHECK(space.part_count() >= 1);
  CHECK_THROWS_AS(Environment({{0.67000000000000004, 0.70000000000000007},
                               {0.67000000000000004, 0.43000000000000005},
                               {0.67000000000000015, 0.43000000000000005},
                               {0.67000000000000015, 0.70000000000000007}},
                              {}),
                  GeometryError);
}
