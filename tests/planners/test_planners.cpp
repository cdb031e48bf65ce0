#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "geometry/occupancy_grid.hpp"
#include "geometry/visibility_graph.hpp"
#include "planners/grid_astar.hpp"
#include "planners/planner_registry.hpp"
#include "planners/planner_run.hpp"
#include "planners/potential_field.hpp"
#include "planners/visibility_graph_planner.hpp"
#include "tests/planners/test_environments.hpp"

using namespace covsim;

namespace {
constexpr double kStep = 0.02;
constexpr std::size_t kMaxSteps = 200000;

PlannerRun go(const Environment& env, Planner& planner, Vec2 start, Vec2 goal, double range) {
  PlannerRun run = run_planner(env, planner, start, goal, range, kStep, kMaxSteps);
  // Never leaves Ω, never steps farther than allowed, and always ends.
  for (std::size_t k = 0; k + 1 < run.path.size(); ++k) {
    REQUIRE(env.segment_inside(run.path[k], run.path[k + 1]));
    REQUIRE(distance(run.path[k], run.path[k + 1]) <= kStep * (1.0 + 1e-12));
  }
  CHECK(run.status != PlanStatus::moving);
  return run;
}

PlannerRun go(const Environment& env, std::string_view name, Vec2 start, Vec2 goal,
              double range = INFINITY) {
  auto planner = make_planner(name, env);
  return go(env, *planner, start, goal, range);
}

struct Case {
  const char* what;
  Environment env;
  Vec2 start, goal;
};

std::vector<Case> reachable_cases() {
  std::vector<Case> c;
  c.push_back({"spiral", test::spiral(), {0.2, 0}, {2, 2.2}});
  c.push_back({"maze", test::serpentine(), {0, 0.2}, {6, 3.8}});
  c.push_back({"comb", test::comb(), {0.5, 0.5}, {9.0, 0.5}});
  c.push_back({"cup", test::room_with_cup(), {3, 0.5}, {3, 2}});
  return c;
}

// Two rooms with square obstacles whose shortest paths are worked out by hand.
Environment one_obstacle() {
  return Environment({{0, 0}, {4, 0}, {4, 2}, {0, 2}},
                     {{{1.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}, {1.5, 1.5}}});
}
Environment two_obstacles() {
  return Environment({{0, 0}, {6, 0}, {6, 3}, {0, 3}},
                     {{{1.8, 0.2}, {2.2, 0.2}, {2.2, 2.0}, {1.8, 2.0}},
                      {{3.8, 1.0}, {4.2, 1.0}, {4.2, 2.8}, {3.8, 2.8}}});
}
}  // namespace

TEST_CASE("TangentBug and the map-based planners reach goals in a spiral, a maze, a comb, a cup",
          "[planners]") {
  for (const Case& c : reachable_cases()) {
    for (const char* name : {"grid_astar", "visibility_graph", "tangent_bug"}) {
      for (double range : {0.5, double(INFINITY)}) {
        INFO(c.what << " with " << name << ", range " << range);
        const PlannerRun run = go(c.env, name, c.start, c.goal, range);
        CHECK(run.status == PlanStatus::reached);
        CHECK(distance(run.path.back(), c.goal) < 1e-6);
      }
    }
  }
}

TEST_CASE("map-based planners send a goal inside an obstacle to the closest point of Ω",
          "[planners]") {
  const Environment env = test::serpentine();
  for (const char* name : {"grid_astar", "visibility_graph"}) {
    for (Vec2 goal : {Vec2{0.6, 2}, Vec2{1.5, 1.55}}) {
      INFO(name << " to (" << goal.x << ", " << goal.y << ")");
      REQUIRE_FALSE(env.contains(goal));
      const PlannerRun run = go(env, name, {0, 0.2}, goal);
      CHECK(run.status == PlanStatus::projected);
      CHECK(distance(run.path.back(), env.closest_point(goal)) < 1e-9);
    }
  }
}

TEST_CASE("the visibility graph finds the hand-computed shortest paths", "[planners]") {
  {
    // Round one square: from the start to a top corner, along the top, down to the goal.
    const Environment env = one_obstacle();
    const VisibilityGraph g(env);
    CHECK(g.vertices().size() == 4);
    const GeodesicPath p = g.shortest_path({0.5, 1}, {3.5, 1});
    REQUIRE(p.found());
    CHECK(p.length == Approx(2.0 * std::sqrt(1.25) + 1.0).epsilon(1e-12));
    CHECK(p.points.size() == 4);
  }
  {
    // Two staggered walls: under the first, then round the second's lower corner, or (the
    // same length, by symmetry) over the first's top and round the second's upper corner.
    const Environment env = two_obstacles();
    const VisibilityGraph g(env);
    const GeodesicPath p = g.shortest_path({1, 1}, {5, 2});
    REQUIRE(p.found());
    const double expected = std::sqrt(1.28) + 0.4 + std::sqrt(4.64) + std::sqrt(1.64);
    CHECK(p.length == Approx(expected).epsilon(1e-12));
    CHECK(p.points.size() == 5);
    // And the planner drives that path, to the step.
    const PlannerRun run = go(env, "visibility_graph", {1, 1}, {5, 2});
    CHECK(run.length == Approx(expected).epsilon(1e-12));
  }
  {
    // In sight: the straight segment.
    const Environment env = one_obstacle();
    const GeodesicPath p = VisibilityGraph(env).shortest_path({0.5, 0.2}, {3.5, 0.3});
    CHECK(p.points.size() == 2);
    CHECK(p.length == Approx(std::hypot(3.0, 0.1)).epsilon(1e-15));
  }
}

TEST_CASE("shortest paths from a tree agree with point-to-point queries", "[planners]") {
  const Environment env = test::serpentine();
  const VisibilityGraph g(env);
  const Vec2 s{0, 0.2};
  const GeodesicTree t = g.tree(s);
  for (std::uint32_t v = 0; v < g.vertices().size(); ++v) {
    const GeodesicPath p = g.shortest_path(s, g.vertices()[v]);
    REQUIRE(p.found());
    CHECK(t.distance[v] == Approx(p.length).epsilon(1e-12));
  }
}

TEST_CASE("A* path length is within the grid's stated tolerance of the shortest path",
          "[planners]") {
  std::vector<Case> cases = reachable_cases();
  cases.push_back({"two obstacles", two_obstacles(), {1, 1}, {5, 2}});
  cases.push_back({"one obstacle", one_obstacle(), {0.5, 1}, {3.5, 1}});
  for (const Case& c : cases) {
    for (double h : {0.02, 0.05}) {
      INFO(c.what << ", h = " << h);
      const GeodesicPath best = VisibilityGraph(c.env).shortest_path(c.start, c.goal);
      REQUIRE(best.found());
      GridAStar planner(c.env, std::make_shared<OccupancyGrid>(c.env, h));
      const PlannerRun run = go(c.env, planner, c.start, c.goal, INFINITY);
      REQUIRE(run.status == PlanStatus::reached);
      CHECK(run.length >= best.length - 1e-9);
      CHECK(run.length <= grid_path_bound(best.length, best.points.size() - 2, h));
    }
  }
}

TEST_CASE("free grid cells lie wholly in Ω", "[planners]") {
  const Environment env = test::serpentine();
  const OccupancyGrid grid(env, 0.05);
  REQUIRE(grid.free_count() > 0);
  REQUIRE(grid.free_count() < grid.size());
  for (std::uint32_t c = 0; c < grid.size(); ++c) {
    if (!grid.free(c)) continue;
    const Vec2 m = grid.center(c);
    const double r = 0.5 * grid.resolution();
    const Vec2 corners[4] = {m + Vec2{-r, -r}, m + Vec2{r, -r}, m + Vec2{r, r}, m + Vec2{-r, r}};
    for (int k = 0; k < 4; ++k)
      REQUIRE(env.segment_inside(corners[k], corners[(k + 1) % 4]));
  }
}

TEST_CASE("straight_line goes straight, and stops at the first wall in its way", "[planners]") {
  const Environment open({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {});
  const PlannerRun free = go(open, "straight_line", {0.5, 0.5}, {3.5, 2.5});
  CHECK(free.status == PlanStatus::reached);
  CHECK(free.length == Approx(std::sqrt(13.0)).epsilon(1e-12));
  // Into the cup's bottom wall from below: stops on the wall at y = 1.
  const Environment cup = test::room_with_cup();
  const PlannerRun blocked = go(cup, "straight_line", {3, 0.5}, {3, 2});
  CHECK(blocked.status == PlanStatus::stalled);
  CHECK(blocked.path.back().y == Approx(1.0).epsilon(1e-12));
  CHECK(blocked.path.back().x == Approx(3.0).epsilon(1e-12));
  // In the spiral, the first wall: it never leaves Ω and ends.
  const PlannerRun spiral = go(test::spiral(), "straight_line", {0.2, 0}, {2, 2.2});
  CHECK(spiral.status == PlanStatus::stalled);
}

TEST_CASE("potential_field reaches goals in the open, in a comb's bay, along a wall",
          "[planners]") {
  for (double range : {0.5, double(INFINITY)}) {
    INFO("range " << range);
    const Environment comb = test::comb();
    // From the hall down into a bay.
    PlannerRun run = go(comb, "potential_field", {5.0, 3.5}, {5.0, 0.5}, range);
    CHECK(run.status == PlanStatus::reached);
    // Round an obstacle in a room, when the way round is downhill.
    const Environment room = one_obstacle();
    run = go(room, "potential_field", {0.5, 0.25}, {3.5, 1.75}, range);
    CHECK(run.status == PlanStatus::reached);
    CHECK(distance(run.path.back(), Vec2{3.5, 1.75}) < 1e-9);
    CHECK_FALSE(room.segment_inside({0.5, 0.25}, {3.5, 1.75}));
    // A goal on a wall.
    run = go(room, "potential_field", {0.5, 1.0}, {1.5, 1.0}, range);
    CHECK(run.status == PlanStatus::reached);
  }
}

TEST_CASE("potential_field reports a stall in local minima: a spiral, a maze, a cup",
          "[planners]") {
  // Where the goal pulls through a wall the descent stops; the planner must say so in
  // bounded time rather than wander or leave Ω.
  for (double range : {0.0, 0.5, double(INFINITY)}) {
    INFO("range " << range);
    CHECK(go(test::spiral(), "potential_field", {0.2, 0}, {2, 2.2}, range).status ==
          PlanStatus::stalled);
    CHECK(go(test::serpentine(), "potential_field", {0, 0.2}, {6, 3.8}, range).status ==
          PlanStatus::stalled);
    const PlannerRun cup = go(test::room_with_cup(), "potential_field", {3, 0.5}, {3, 2}, range);
    CHECK(cup.status == PlanStatus::stalled);
    CHECK(cup.steps < 2000);
  }
}

TEST_CASE("every planner ends in bounded time on a goal inside an obstacle", "[planners]") {
  const Environment env = test::room_with_cup();
  for (const std::string& name : planner_registry().names()) {
    INFO(name);
    // One that does not avoid obstacles drives into the wall; the controller ends that run
    // (left_environment; the next test).
    if (!make_planner(name, env)->avoids_obstacles()) continue;
    const PlannerRun run = go(env, name, {1, 2}, {2.05, 2}, 0.5);
    CHECK(run.status != PlanStatus::reached);
  }
}

TEST_CASE("without a planner the robot is sent straight through the wall", "[planners]") {
  const Environment env = test::room_with_cup();
  auto none = make_planner("none", env);
  CHECK_FALSE(none->avoids_obstacles());
  CHECK(make_planner("tangent_bug", env)->avoids_obstacles());
  // Across the cup's bottom to a goal inside it: every step is a full one along the line,
  // walls or not, until the goal.
  const Vec2 start{3, 0.5}, goal{3, 2};
  none->set_goal(goal);
  Vec2 x = start;
  bool crossed = false;
  for (int k = 0; k < 1000; ++k) {
    const PlanStep s = none->step(sense(env, x, 0.0), 0.1);
    CHECK(std::abs(cross(s.next - start, goal - start)) < 1e-12);
    crossed = crossed || !env.segment_inside(x, s.next);
    x = s.next;
    if (s.status != PlanStatus::moving) {
      CHECK(s.status == PlanStatus::reached);
      break;
    }
    CHECK(distance(x, start) == Approx(0.1 * (k + 1)));
  }
  CHECK(x == goal);
  CHECK(crossed);
}

TEST_CASE("the registry knows every planner and rejects others", "[planners]") {
  const Environment env = one_obstacle();
  for (const std::string& name : planner_registry().names())
    CHECK(make_planner(name, env)->name() == name);
  CHECK_THROWS_WITH(make_planner("rrt", env), Catch::Contains("unknown planner \"rrt\""));
}
