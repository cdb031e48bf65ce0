#include <catch2/catch.hpp>

#include <cmath>

#include "planners/planner_run.hpp"
#include "planners/tangent_bug.hpp"
#include "tests/planners/test_environments.hpp"

using namespace covsim;

namespace {
double boundary_length(const Environment& env) {
  double l = 0;
  for (const auto& e : env.boundary())
    l += distance(e.a, e.b);
  return l;
}

PlannerRun go(const Environment& env, Vec2 start, Vec2 goal, double range) {
  TangentBug bug(TangentBugParams::for_environment(env.diameter(), boundary_length(env)));
  PlannerRun run = run_planner(env, bug, start, goal, range, 0.02, 200000);
  // The path never leaves Ω.
  for (std::size_t k = 0; k + 1 < run.path.size(); ++k)
    REQUIRE(env.segment_inside(run.path[k], run.path[k + 1]));
  return run;
}

void expect_reached(const Environment& env, Vec2 start, Vec2 goal, double range) {
  INFO("range " << range << ", goal (" << goal.x << ", " << goal.y << ")");
  const PlannerRun run = go(env, start, goal, range);
  CHECK(run.status == PlanStatus::reached);
  CHECK(distance(run.path.back(), goal) < 1e-6);
}

void expect_projected(const Environment& env, Vec2 start, Vec2 goal, double range) {
  INFO("range " << range << ", goal (" << goal.x << ", " << goal.y << ")");
  REQUIRE_FALSE(env.contains(goal));
  const PlannerRun run = go(env, start, goal, range);
  CHECK(run.status == PlanStatus::projected);
  const Vec2 p = env.closest_point(goal);
  CHECK(distance(run.path.back(), p) < 1e-6);
}

const double kRanges[] = {0.0, 0.5, INFINITY};
}  // namespace

TEST_CASE("TangentBug reaches goals through a spiral corridor", "[tangent_bug]") {
  const Environment env = test::spiral();
  for (double r : kRanges)
    expect_reached(env, {0.2, 0}, {2, 2.2}, r);
}

TEST_CASE("TangentBug declares a goal in the spiral's wall unreachable and projects it",
          "[tangent_bug]") {
  const Environment env = test::spiral();
  for (double r : kRanges)
    expect_projected(env, {0.2, 0}, {2, 0.4}, r);
}

TEST_CASE("TangentBug reaches the end of a serpentine maze with pillars", "[tangent_bug]") {
  const Environment env = test::serpentine();
  for (double r : kRanges)
    expect_reached(env, {0, 0.2}, {6, 3.8}, r);
}

TEST_CASE("TangentBug projects goals between the maze's runs and inside a pillar",
          "[tangent_bug]") {
  const Environment env = test::serpentine();
  for (double r : kRanges) {
    expect_projected(env, {0, 0.2}, {0.6, 2}, r);
    expect_projected(env, {0, 0.2}, {1.5, 1.55}, r);
  }
}

TEST_CASE("TangentBug escapes the inside of a cup and gets into another", "[tangent_bug]") {
  const Environment env = test::room_with_cup();
  for (double r : kRanges) {
    expect_reached(env, {3, 0.5}, {3, 2}, r);     // into the cup, from below
    expect_reached(env, {3, 2}, {3, 0.5}, r);     // and out again
    expect_projected(env, {1, 2}, {2.05, 2}, r);  // inside the cup's wall
  }
}

TEST_CASE("TangentBug remembers an obstacle it circled: a new goal inside it is projected at once",
          "[tangent_bug]") {
  const Environment env = test::room_with_cup();
  TangentBug bug(TangentBugParams::for_environment(env.diameter(), boundary_length(env)));
  const PlannerRun first = run_planner(env, bug, {1, 2}, {2.05, 2}, 0.5, 0.02, 100000);
  REQUIRE(first.status == PlanStatus::projected);
  const PlannerRun second =
      run_planner(env, bug, first.path.back(), {2.05, 1.5}, 0.5, 0.02, 100000);
  CHECK(second.status == PlanStatus::projected);
  CHECK(distance(second.path.back(), Vec2{2, 1.5}) < 1e-6);
  CHECK(second.length == Approx(0.5).epsilon(1e-6));  // straight down the wall, no second loop
}

TEST_CASE("TangentBug in open space goes straight", "[tangent_bug]") {
  const Environment env({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {});
  for (double r : kRanges) {
    const PlannerRun run = go(env, {0.5, 0.5}, {3.5, 2.5}, r);
    CHECK(run.status == PlanStatus::reached);
    CHECK(run.length == Approx(std::sqrt(9.0 + 4.0)).epsilon(1e-9));
  }
}

TEST_CASE("TangentBug ends within its path budget even when cornered", "[tangent_bug]") {
  // A goal outside the room: the outer ring is circled once, then the closest point.
  const Environment env({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {});
  for (double r : kRanges)
    expect_projected(env, {1, 1}, {5, 2}, r);
}
