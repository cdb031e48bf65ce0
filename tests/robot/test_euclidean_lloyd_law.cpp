// Lloyd on the real positions (robot/euclidean_lloyd_law): each robot's target is the centroid
// of its own Voronoi cell ∩ Ω among the positions it knows.
#include <catch2/catch.hpp>

#include "robot/euclidean_lloyd_law.hpp"
#include "tests/robot/law_cases.hpp"

using namespace covsim;
using namespace covsim::test;

TEST_CASE("Euclidean Lloyd sends two robots in a square to the centroids of its halves", "[law]") {
  const Environment env = unit_square();
  const std::vector<Vec2> p{{0.2, 0.3}, {0.8, 0.3}};
  Shared shared(env, p);
  EuclideanLloydLaw law(shared.integrator);
  CHECK(law.generators() == Generators::positions);
  CHECK_FALSE(law.moves_virtual_generators());
  const Vec2 want[] = {{0.25, 0.5}, {0.75, 0.5}};
  for (std::uint32_t i = 0; i < 2; ++i) {
    INFO("robot " << i);
    const Robot r = robot_at(i, p[i]);
    const Vec2 t = law.target(r, shared.knowledge(i, Generators::positions));
    CHECK(t.x == Approx(want[i].x).epsilon(0).margin(1e-12));
    CHECK(t.y == Approx(want[i].y).epsilon(0).margin(1e-12));
    // A robot computing its own cell from what it heard gets the same.
    CHECK(distance(law.target(r, own(p, i, Generators::positions)), t) < 1e-12);
    CHECK(law.at_rest(r, Tolerances{1e-3, 1e-3}));  // nothing of its own to wait for
  }
  // A robot that has heard nobody covers Ω alone: its centroid.
  const std::vector<Vec2> alone{{0.1, 0.9}};
  const Vec2 c = law.target(robot_at(0, alone[0]), own(alone, 0, Generators::positions));
  CHECK(c.x == Approx(0.5).epsilon(0).margin(1e-12));
  CHECK(c.y == Approx(0.5).epsilon(0).margin(1e-12));
}

TEST_CASE("Euclidean Lloyd integrates over cell ∩ Ω round a hole", "[law]") {
  const Environment env = square_with_hole();
  const std::vector<Vec2> p{{0.2, 0.5}, {0.8, 0.5}};
  Shared shared(env, p);
  EuclideanLloydLaw law(shared.integrator);
  const Vec2 left = law.target(robot_at(0, p[0]), shared.knowledge(0, Generators::positions));
  const Vec2 right = law.target(robot_at(1, p[1]), shared.knowledge(1, Generators::positions));
  CHECK(left.x == Approx(kHoledHalfCentroidX).epsilon(0).margin(1e-12));
  CHECK(left.y == Approx(0.5).epsilon(0).margin(1e-12));
  CHECK(right.x == Approx(1.0 - kHoledHalfCentroidX).epsilon(0).margin(1e-12));
  CHECK(right.y == Approx(0.5).epsilon(0).margin(1e-12));
}
