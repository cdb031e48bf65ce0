// The sensed map (planners/sensed_map) and the map planners on it: what a leg may cross, where
// it may start and end, which goals are unreachable and where they end, against hand-worked
// cases; and that a sensed map planner depends on the sensor's range where the given map
// does not.
#include <catch2/catch.hpp>

#include <cmath>

#include "planners/planner_registry.hpp"
#include "planners/planner_run.hpp"
#include "planners/sensed_map.hpp"
#include "planners/sensed_map_planner.hpp"
#include "tests/planners/test_environments.hpp"

using namespace covsim;

namespace {
// A 4 m x 2 m room with a 1 m square box in its middle.
Environment room_with_box() {
  return Environment({{0, 0}, {4, 0}, {4, 2}, {0, 2}},
                     {{{1.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}, {1.5, 1.5}}});
}

Box room_box() {
  Box b;
  b.add({0, 0});
  b.add({4, 2});
  return b;
}

// The box's walls as a robot below-left of it sees them (free space on the left of each).
SensedMap box_map(double h = 0.05) {
  SensedMap m(room_box(), h, 1e-9);
  m.add_wall({1.5, 0.5}, {1.5, 1.5});  // west face, seen from the west: free on its left
  m.add_wall({2.5, 0.5}, {1.5, 0.5});  // south face, free below it
  return m;
}

Params sensed(double resolution) {
  Params p;
  p.set("map", std::string("sensed"));
  p.set("resolution", resolution);
  return p;
}

std::unique_ptr<Planner> sensed_planner(std::string_view type, const Environment& env,
                                        double resolution) {
  PlannerConfig c;
  c.type = std::string(type);
  c.params = sensed(resolution);
  return planner_source(c, PlannerContext{env, SensorSpec{}})();
}
}  // namespace

TEST_CASE("sensed map: a cell is a wall cell where a piece touches its closed square",
          "[sensed_map]") {
  SensedMap m(room_box(), 0.5, 1e-9);
  CHECK(m.wall_cells() == 0);
  // Along the cell line x = 1.5 (cells start at -1 with the two-cell margin): both columns.
  m.add_wall({1.5, 0.6}, {1.5, 0.9});
  CHECK(m.wall_cells() == 2);
  CHECK_FALSE(m.free(m.column(m.cell_of({1.4, 0.7})), m.row(m.cell_of({1.4, 0.7}))));
  CHECK_FALSE(m.free(m.column(m.cell_of({1.6, 0.7})), m.row(m.cell_of({1.6, 0.7}))));
  CHECK(m.free(m.column(m.cell_of({0.7, 0.7})), m.row(m.cell_of({0.7, 0.7}))));
  // Outside the grid counts as wall.
  CHECK_FALSE(m.free(-1, 0));
  CHECK_FALSE(m.free(m.nx(), 0));
}

TEST_CASE("sensed map: a piece held already adds nothing, a new stretch of it does",
          "[sensed_map]") {
  SensedMap m(room_box(), 0.05, 1e-9);
  CHECK(m.add_wall({2.5, 0.5}, {1.5, 0.5}));
  CHECK_FALSE(m.add_wall({2.2, 0.5}, {1.7, 0.5}));  // covered
  CHECK(m.pieces().size() == 1);
  CHECK(m.add_wall({2.8, 0.5}, {2.2, 0.5}));  // runs beyond it: extends it
  REQUIRE(m.pieces().size() == 1);
  CHECK(m.pieces()[0].a == Vec2{2.8, 0.5});
  CHECK(m.pieces()[0].b == Vec2{1.5, 0.5});
  CHECK(m.add_wall({1.6, 0.5}, {2.0, 0.5}));  // the same line, the other side free
  CHECK(m.pieces().size() == 2);
  // What was new each time, in order.
  REQUIRE(m.added().size() == 3);
  CHECK(m.added()[1].a == Vec2{2.8, 0.5});
  CHECK(m.added()[1].b == Vec2{2.5, 0.5});
  // A stretch between two pieces of one wall joins the first to the second's start; one
  // apart from both is a piece of its own.
  SensedMap w(room_box(), 0.05, 1e-9);
  CHECK(w.add_wall({0.5, 1.0}, {1.0, 1.0}));
  CHECK(w.add_wall({2.0, 1.0}, {3.0, 1.0}));
  CHECK(w.add_wall({0.8, 1.0}, {2.5, 1.0}));
  REQUIRE(w.pieces().size() == 2);
  CHECK(w.pieces()[0].b == Vec2{2.0, 1.0});
  CHECK(w.added().back().a == Vec2{1.0, 1.0});
  CHECK(w.added().back().b == Vec2{2.0, 1.0});
  CHECK(w.add_wall({3.2, 1.0}, {3.5, 1.0}));
  CHECK(w.pieces().size() == 3);
  // Every point of the stretches seen is on a wall cell.
  for (double x = 0.5; x <= 3.0; x += 0.01)
    CHECK_FALSE(w.free(w.column(w.cell_of({x, 1.0})), w.row(w.cell_of({x, 1.0}))));
}

TEST_CASE("sensed map: a leg may not cross a sensed wall, nor cut through a corner",
          "[sensed_map]") {
  const SensedMap m = box_map();
  CHECK_FALSE(m.clear({1.0, 1.0}, {2.0, 1.0}));  // through the west face
  CHECK_FALSE(m.clear({2.0, 0.2}, {2.0, 1.0}));  // through the south face
  CHECK(m.clear({0.2, 0.2}, {1.2, 0.3}));        // in the open
  // Past the corner (1.5, 0.5) outside the box, and through it into the box.
  CHECK(m.clear({1.0, 0.0}, {2.0, 0.0}));
  CHECK_FALSE(m.clear({1.0, 0.0}, {2.0, 1.0}));
  // Through the box's unseen faces: unseen space is free.
  CHECK(m.clear({3.0, 1.0}, {2.0, 1.0}));
  CHECK(m.clear({2.0, 1.8}, {2.0, 1.0}));
}

TEST_CASE("sensed map: a leg that starts or ends on a wall leaves it on its free side",
          "[sensed_map]") {
  const SensedMap m = box_map();
  const Vec2 on_west{1.5, 1.0}, on_south{2.0, 0.5};
  CHECK(m.clear(on_west, {1.0, 1.2}));
  CHECK_FALSE(m.clear(on_west, {1.8, 1.0}));  // into the box
  CHECK(m.clear({2.2, 0.1}, on_south));
  CHECK_FALSE(m.clear({2.0, 1.0}, on_south));  // from inside
  // At the corner, a convex one of the obstacle: any way but into the box.
  CHECK(m.clear({1.5, 0.5}, {1.0, 0.1}));
  CHECK(m.clear({1.5, 0.5}, {2.0, 0.2}));
  CHECK_FALSE(m.clear({1.5, 0.5}, {2.0, 1.0}));
}

TEST_CASE("sensed map: a point enters the grid by the nearest free cell it sees", "[sensed_map]") {
  const SensedMap m = box_map(0.1);
  const auto e = m.entry({1.5, 1.0});  // on the west face
  REQUIRE(e);
  CHECK(m.center(*e).x < 1.5);
  CHECK(distance(m.center(*e), {1.5, 1.0}) < 0.25);
}

TEST_CASE("sensed map: the closest reachable wall point to a goal cut off by it", "[sensed_map]") {
  // The box seen whole: its inside is cut off from the room; the goal (2.2, 0.9) inside is
  // 0.3 m from the east face, 0.4 m from the south face; the closest point is (2.5, 0.9).
  const Environment env = room_with_box();
  SensedMap m(room_box(), 0.05, 1e-9);
  for (std::size_t k = 0; k < env.boundary().size(); ++k)
    m.add_wall(env.boundary()[k].a, env.boundary()[k].b);
  std::vector<std::uint8_t> reach(m.size(), 0);
  for (std::int32_t j = 0; j < m.ny(); ++j)
    for (std::int32_t i = 0; i < m.nx(); ++i) {
      const Vec2 c = m.center(m.index(i, j));
      reach[m.index(i, j)] = m.free(i, j) && env.contains(c) ? 1 : 0;
    }
  const auto landing = m.closest_reachable_wall({2.2, 0.9}, reach);
  REQUIRE(landing);
  CHECK(landing->point.x == Approx(2.5));
  CHECK(landing->point.y == Approx(0.9));
}

TEST_CASE("sensed map planners: reach goals in Ω, project goals in an unseen obstacle",
          "[sensed_map]") {
  const Environment env = room_with_box();
  for (const char* type : {"grid_astar", "visibility_graph"}) {
    for (double range : {0.0, 0.5, double(INFINITY)}) {
      INFO(type << " range " << range);
      auto planner = sensed_planner(type, env, 0.05);
      const PlannerRun across =
          run_planner(env, *planner, {0.5, 1.0}, {3.5, 1.0}, range, 0.02, 100000);
      CHECK(across.status == PlanStatus::reached);
      CHECK(distance(across.path.back(), {3.5, 1.0}) <= 1e-9);
      for (std::size_t k = 0; k + 1 < across.path.size(); ++k)
        REQUIRE(env.segment_inside(across.path[k], across.path[k + 1]));
      // The way round the box is at least 2 (sqrt(1 + 0.25) + ...) longer than straight.
      CHECK(across.length > 3.0);
      // A goal inside the box: found unreachable once its faces are seen, and settled at the
      // closest point of its boundary, (2.5, 0.9).
      auto inside = sensed_planner(type, env, 0.05);
      const PlannerRun in = run_planner(env, *inside, {0.5, 1.0}, {2.2, 0.9}, range, 0.02, 100000);
      CHECK(in.status == PlanStatus::projected);
      CHECK(distance(in.path.back(), {2.5, 0.9}) <= 1e-6);
    }
  }
}

TEST_CASE("sensed map planners: the path depends on the range, the given map's does not",
          "[sensed_map]") {
  // A goal inside a cup that opens away from the robot: what it sees from where it stands
  // decides the way round, so the walks differ with the range; on the given map they do not.
  const Environment env = test::room_with_cup();
  const Vec2 start{3, 0.5}, goal{3, 2};
  for (const char* type : {"grid_astar", "visibility_graph"}) {
    INFO(type);
    auto short_range = sensed_planner(type, env, 0.05);
    auto long_range = sensed_planner(type, env, 0.05);
    const PlannerRun near = run_planner(env, *short_range, start, goal, 0.3, 0.02, 100000);
    const PlannerRun far = run_planner(env, *long_range, start, goal, INFINITY, 0.02, 100000);
    REQUIRE(near.status == PlanStatus::reached);
    REQUIRE(far.status == PlanStatus::reached);
    CHECK(far.length != near.length);
    CHECK(dynamic_cast<const SensedMapPlanner&>(*short_range).replans() > 0);
    auto given_near = make_planner(type, env);
    auto given_far = make_planner(type, env);
    CHECK(run_planner(env, *given_near, start, goal, 0.3, 0.02, 100000).length ==
          run_planner(env, *given_far, start, goal, INFINITY, 0.02, 100000).length);
  }
}

TEST_CASE("sensed map planners of a centralized run share one map", "[sensed_map]") {
  const Environment env = room_with_box();
  PlannerConfig c;
  c.type = "grid_astar";
  c.params = sensed(0.05);
  for (const bool shared : {false, true}) {
    INFO("shared " << shared);
    const PlannerSource source = planner_source(c, PlannerContext{env, SensorSpec{}, shared});
    auto a = source(), b = source();
    a->set_goal({3.5, 1.0});
    a->step(sense(env, {0.5, 1.0}, INFINITY), 0.02);
    const auto& map_a = dynamic_cast<const SensedMapPlanner&>(*a).map();
    const auto& map_b = dynamic_cast<const SensedMapPlanner&>(*b).map();
    CHECK(map_a.pieces().size() > 0);
    CHECK((&map_a == &map_b) == shared);
    CHECK(map_b.pieces().size() == (shared ? map_a.pieces().size() : 0));
  }
}

TEST_CASE("sensed map: a touch shows the wall where the robot stands, not the whole edge",
          "[sensed_map]") {
  // A contact sensor on the room's 4 m bottom wall learns a cell's side either way of the
  // touch.
  const Environment env = room_with_box();
  SensedMap m(room_box(), 0.05, 1e-9);
  const SensorReading touch = sense(env, {1.0, 0.0}, 0.0);
  REQUIRE_FALSE(touch.contacts.empty());
  CHECK(m.add(touch));
  REQUIRE(m.pieces().size() == 1);
  const SensedMap::Piece& p = m.pieces()[0];
  CHECK(distance(p.a, p.b) == Approx(0.1));
  CHECK(std::min(p.a.x, p.b.x) == Approx(0.95));
  CHECK(p.a.y == 0.0);
  CHECK(p.b.y == 0.0);
}

TEST_CASE("sensed map planners: walls a neighbour shares reroute the path", "[sensed_map]") {
  // Range 0: the robot's own readings show nothing ahead, so it plans straight through the
  // box; the box's west face, heard from a neighbour, sends the path round it.
  const Environment env = room_with_box();
  for (const char* type : {"grid_astar", "visibility_graph"}) {
    INFO(type);
    auto planner = sensed_planner(type, env, 0.05);
    planner->set_goal({3.5, 1.0});
    const Vec2 x{0.5, 1.0};
    planner->step(sense(env, x, 0.0), 0.02);
    const auto& p = dynamic_cast<const SensedMapPlanner&>(*planner);
    REQUIRE(p.path().size() == 2);  // straight to the goal
    planner->learn({{{1.5, 0.5}, {1.5, 1.5}}, {{2.5, 0.5}, {1.5, 0.5}}});
    CHECK(p.map().pieces().size() == 2);
    planner->step(sense(env, x, 0.0), 0.02);
    CHECK(p.replans() > 0);
    const auto& path = p.path();
    REQUIRE(path.size() > 2);
    // Clear of the walls heard (the faces not yet seen may still be crossed: unseen space is
    // free).
    for (std::size_t k = 0; k + 1 < path.size(); ++k)
      CHECK(p.map().clear(path[k], path[k + 1]));
    CHECK_FALSE(p.map().clear(x, {3.5, 1.0}));
    // Planners without a map have nowhere to keep them.
    auto bug = make_planner("tangent_bug", env);
    bug->learn({{{1.5, 0.5}, {1.5, 1.5}}});
  }
}

TEST_CASE("sensed map: under range noise a touch is exact, and a noisy wall traps no one",
          "[sensed_map]") {
  // σ = 1 cm: the box's west face was seen 2 cm into the room (x = 1.48).
  SensedMap m(room_box(), 0.05, 1e-9, 0.01);
  m.add_wall({1.48, 0.5}, {1.48, 1.5});
  REQUIRE(m.pieces().size() == 1);
  CHECK_FALSE(m.pieces()[0].exact);
  // Seen again 1 cm off: within 3σ, the same wall.
  CHECK_FALSE(m.add_wall({1.49, 0.6}, {1.49, 1.4}));
  // Touched where it is: a new, exact stretch however near the noisy one, which it
  // supersedes beside it (a cell's side either way of the touch, y in [0.95, 1.05]).
  const Environment env = room_with_box();
  CHECK(m.add(sense(env, {1.5, 1.0}, 0.0)));
  REQUIRE(m.pieces().size() == 3);
  int exact_pieces = 0;
  for (const SensedMap::Piece& p : m.pieces()) {
    INFO("piece (" << p.a.x << ", " << p.a.y << ") -> (" << p.b.x << ", " << p.b.y << ")");
    if (p.exact) {
      ++exact_pieces;
      CHECK(p.a.x == 1.5);
      CHECK(std::min(p.a.y, p.b.y) == Approx(0.95));
      CHECK(std::max(p.a.y, p.b.y) == Approx(1.05));
    } else {
      CHECK(p.a.x == 1.48);
      CHECK((std::max(p.a.y, p.b.y) <= 0.95 + 1e-12 || std::min(p.a.y, p.b.y) >= 1.05 - 1e-12));
    }
  }
  CHECK(exact_pieces == 1);
  // A noisy stretch that continues the touched piece is a piece of its own: the touched one
  // stays exact.
  SensedMap fresh(room_box(), 0.05, 1e-9, 0.01);
  CHECK(fresh.add(sense(env, {1.5, 1.0}, 0.0)));
  CHECK(fresh.add_wall({1.5, 1.05}, {1.5, 1.4}));
  REQUIRE(fresh.pieces().size() == 2);
  CHECK(fresh.pieces()[0].exact);
  CHECK(std::max(fresh.pieces()[0].a.y, fresh.pieces()[0].b.y) == Approx(1.05));
  CHECK_FALSE(fresh.pieces()[1].exact);
  // Just behind the true face (x = 1.505, within 3σ of the wall seen): reachable from the
  // room by the noisy wall alone, behind an exact wall beside the touch.
  CHECK_FALSE(m.clear({1.0, 1.0}, {1.505, 1.0}));
  CHECK(m.clear({1.0, 0.7}, {1.505, 0.7}));
  // A robot standing between the noisy wall and the true one (x = 1.49) leaves to the free
  // side, not into the box; on an exact wall the leeway is the tolerance only.
  CHECK(m.clear({1.49, 0.8}, {1.0, 0.8}));
  CHECK_FALSE(m.clear({1.49, 0.8}, {1.8, 0.8}));
  SensedMap exact(room_box(), 0.05, 1e-9);
  exact.add_wall({1.48, 0.5}, {1.48, 1.5});
  CHECK_FALSE(exact.clear({1.49, 0.8}, {1.0, 0.8}));
}

namespace {
// A sensed-map planner of `type` (σ = 1 cm, 5 cm cells) walking from (0.5, 1) to `goal` in
// `env`, every reading showing the wall on x = 1.5 at x = `seen_at` instead: where it ends,
// how, and the length of its way.
struct Walk {
  Vec2 end;
  PlanStatus status = PlanStatus::moving;
  double path = 0.0;
};
Walk walk_past_a_shifted_wall(const char* type, const Environment& env, Vec2 goal, double seen_at) {
  PlannerConfig c;
  c.type = type;
  c.params = sensed(0.05);
  auto planner = planner_source(c, PlannerContext{env, SensorSpec{0.01}})();
  planner->set_goal(goal);
  Walk w{{0.5, 1.0}};
  for (int k = 0; k < 4000 && w.status == PlanStatus::moving; ++k) {
    SensorReading r = sense(env, w.end, 0.5);
    for (SensedPiece& p : r.visible().pieces)
      if (p.a.x == 1.5 && p.b.x == 1.5) p.a.x = p.b.x = seen_at;
    const PlanStep s = planner->step(r, 0.02);
    const Vec2 next = env.advance(w.end, s.next);
    w.path += distance(w.end, next);
    w.end = next;
    w.status = s.status;
  }
  return w;
}
}  // namespace

TEST_CASE("sensed map planners under range noise settle by touch on ∂Ω", "[sensed_map]") {
  // σ = 1 cm, and every reading shows the box's west face 2 cm too near (x = 1.48, within
  // the noise). A goal inside the box ends on the true face, not on the wall seen in front of
  // it; a goal 1 cm off the face, in the room but behind the wall seen, is reached.
  const Environment env = room_with_box();
  for (const char* type : {"grid_astar", "visibility_graph"}) {
    for (const Vec2 goal : {Vec2{1.8, 1.0}, Vec2{1.49, 1.0}}) {
      INFO(type << ", goal (" << goal.x << ", " << goal.y << ")");
      const Walk w = walk_past_a_shifted_wall(type, env, goal, 1.48);
      if (goal.x > 1.5) {
        CHECK(w.status == PlanStatus::projected);
        CHECK(w.end.x == Approx(1.5).margin(1e-9));
        CHECK(w.end.y == Approx(1.0).margin(1e-6));
      } else {
        CHECK(w.status == PlanStatus::reached);
        CHECK(distance(w.end, goal) <= 1e-9);
      }
    }
  }
}

TEST_CASE("sensed map planners under range noise reach a goal on a thin wall's far face",
          "[sensed_map]") {
  // A wall 3 cm thick (x from 1.5 to 1.53), every reading showing its west face 2 cm too far
  // (x = 1.52, within the noise): the goal on its east face lies within 3σ of the wall seen,
  // so the map lets the robot reach it from the west. The touch at x = 1.5 shows the goal
  // behind the wall; the robot goes round and reaches it.
  const Environment env({{0, 0}, {4, 0}, {4, 2}, {0, 2}},
                        {{{1.5, 0.5}, {1.53, 0.5}, {1.53, 1.5}, {1.5, 1.5}}});
  const Vec2 goal{1.53, 1.0};
  for (const char* type : {"grid_astar", "visibility_graph"}) {
    INFO(type);
    const Walk w = walk_past_a_shifted_wall(type, env, goal, 1.52);
    CHECK(w.status == PlanStatus::reached);
    CHECK(distance(w.end, goal) <= 1e-9);
    CHECK(w.path > 2.0);  // round the wall, not through it
  }
}
