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
