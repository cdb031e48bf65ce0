// The body checks (robot/body_checks): the least gap between two bodies, the robot-seconds
// bodies overlap, and arrivals with a body overlapping a wall, on positions set by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "robot/body_checks.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

TEST_CASE("body checks: the least gap, the contact time and the wall contacts", "[layers]") {
  const Environment env(square(0, 0, 1, 1), {});
  const ConfigurationSpace space(env, 0.1);
  BodyChecks bodies(env, space, 0.1, 0.05);
  std::vector<Robot> robots(3);
  robots[0].position = {0.3, 0.5};
  robots[1].position = {0.55, 0.5};
  robots[2].position = {0.8, 0.9};
  CHECK(std::isnan(bodies.gap_min()));  // nothing compared yet
  bodies.after_tick(robots);
  CHECK(bodies.gap_min() == Approx(0.05));  // 0.25 apart, 0.2 of bodies
  CHECK(bodies.contact_time() == 0.0);
  // Two bodies overlapping for one tick: 0.05 s each.
  robots[1].position = {0.45, 0.5};
  bodies.after_tick(robots);
  CHECK(bodies.gap_min() == Approx(-0.05));
  CHECK(bodies.contact_time() == Approx(0.1));
  // Apart again: the least gap stays the least over the run.
  robots[1].position = {0.7, 0.5};
  bodies.after_tick(robots);
  CHECK(bodies.gap_min() == Approx(-0.05));
  CHECK(bodies.contact_time() == Approx(0.1));
  // A body 0.05 m from a wall overlaps it; one at the middle does not.
  bodies.arrived({0.05, 0.5});
  bodies.arrived({0.5, 0.5});
  CHECK(bodies.wall_contacts() == 1);
}
