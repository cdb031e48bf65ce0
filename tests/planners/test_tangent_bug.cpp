#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <set>

#include "geometry/reversals.hpp"
#include "planners/planner_run.hpp"
#include "planners/recorded_obstacle.hpp"
#include "planners/sensor_reading.hpp"
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
constexpr double kInfinity = std::numeric_limits<double>::infinity();
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
  // A goal outside the room: at most once round the outer ring, then the closest point (a
  // contact sensor goes the whole way round, 19.34 m; an unlimited range sees that the
  // closest point is (4, 2) and goes straight there).
  const Environment env({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {});
  const double budget =
      TangentBugParams::for_environment(env.diameter(), boundary_length(env)).path_budget;
  CHECK(budget == Approx(10 * (16 + std::sqrt(32.0))));  // 10 × (∂Ω + diameter)
  // Straight to the wall at (4, 1.75), once round the 16 m ring, and 0.25 m to (4, 2).
  const double once_round = 0.75 * std::sqrt(17.0) + 16.0 + 0.25;
  for (double r : kRanges) {
    expect_projected(env, {1, 1}, {5, 2}, r);
    const PlannerRun run = go(env, {1, 1}, {5, 2}, r);
    INFO("range " << r << ": path " << run.length << " m");
    CHECK(run.length <= budget);
    CHECK(run.length <= once_round + 1e-6);
  }
}

namespace {
// The paper's U-shaped room: a slot from the top between x = 0.35 and 0.65 down to y = 0.35.
Environment u_room() {
  return Environment(
      {{0, 0}, {1, 0}, {1, 1}, {0.65, 1}, {0.65, 0.35}, {0.35, 0.35}, {0.35, 1}, {0, 1}}, {});
}
}  // namespace

TEST_CASE("TangentBug standing on the corner it headed for follows on in its direction of motion",
          "[tangent_bug]") {
  // From the left arm toward the right one: the slot's corner (0.35, 0.35) is the best node;
  // there the heuristic stops falling, and the wall is followed the way the robot was moving
  // (to the right, under the slot), not the way the goal lies (up the slot's side, round the
  // whole room).
  const Environment env = u_room();
  const Vec2 start{0.3, 0.6}, goal{0.742, 0.799}, c1{0.35, 0.35}, c2{0.65, 0.35};
  const double shortest = distance(start, c1) + distance(c1, c2) + distance(c2, goal);
  for (double r : {0.5, kInfinity}) {
    INFO("range " << r);
    const PlannerRun run = go(env, start, goal, r);
    CHECK(run.status == PlanStatus::reached);
    CHECK(run.length <= shortest * (1.0 + 1e-9));
  }
}

TEST_CASE("TangentBug walks the U's slot bottom once on its way to a target in the slot",
          "[tangent_bug]") {
  // A leg of the studies' u_shape run 19 (docs/studies.md): from the left arm to a target
  // 1 mm inside the slot's right wall. Round the corner at the slot's bottom the robot saw
  // the whole bottom of the room from the far corner, and the far end of that stretch lay
  // straight back along the slot's bottom: it walked the bottom to its right end, back to
  // its left end and again to the right. It now keeps its direction: down round the room
  // until the loop closes, then the shorter way to the projection, without walking back
  // over its own way.
  const Environment env = u_room();
  const Vec2 start{0.22257261661109454, 0.8938761955184795};
  const Vec2 goal{0.6494769838517639, 0.9009757137187664};
  for (double r : {0.5, 2.0, kInfinity}) {
    INFO("range " << r);
    TangentBug bug(TangentBugParams::for_environment(env.diameter(), boundary_length(env)));
    const PlannerRun run = run_planner(env, bug, start, goal, r, 0.01, 20000);
    CHECK(run.status == PlanStatus::projected);
    CHECK(distance(run.path.back(), Vec2{0.65, goal.y}) < 1e-9);
    CHECK(bug.loops() == 1);
    // No five steps back over its way within a step of it.
    CHECK(reversals(run.path, 0.05, 0.01).empty());
  }
}

TEST_CASE("TangentBug keeps its episode while its goal moves", "[tangent_bug]") {
  // A periodic loop 1 moves the goal a little every step while the robot turns the slot's
  // corner. Kept episodes carry the robot under the slot; a restart at every move would head
  // back to the corner behind (its straight-line heuristic is the better one) and shuttle.
  const Environment env = u_room();
  for (double r : {0.5, kInfinity}) {
    INFO("range " << r);
    TangentBug bug(TangentBugParams::for_environment(env.diameter(), boundary_length(env)));
    Vec2 x{0.3, 0.6}, goal{0.83, 0.53};
    const Vec2 end_goal{0.83, 0.74}, c1{0.35, 0.35}, c2{0.65, 0.35};  // the goal's last place
    bug.set_goal(goal);
    double length = 0.0;
    PlanStatus status = PlanStatus::moving;
    for (int k = 0; k < 2000 && status == PlanStatus::moving; ++k) {
      if (k % 2 == 0 && !(goal == end_goal)) {
        goal = Vec2{0.83, std::min(end_goal.y, goal.y + 0.003)};
        bug.move_goal(goal);
      }
      const PlanStep s = bug.step(sense(env, x, r), 0.01);
      const Vec2 next = env.advance(x, s.next);
      REQUIRE(env.segment_inside(x, next));
      length += distance(x, next);
      x = next;
      status = s.status;
    }
    CHECK(status == PlanStatus::reached);
    CHECK(distance(x, goal) < 1e-6);
    // The way round the corners to where the goal was reached, and the goal's own motion.
    const double shortest = distance({0.3, 0.6}, c1) + distance(c1, c2) + distance(c2, goal);
    CHECK(length <= shortest + distance({0.83, 0.53}, goal));
  }
}

namespace {
// A comb between the robot and its goal: a bar along y in [1.2, 1.35] with seven teeth
// 1.2 m deep pointing down, 0.4 m apart. The goal lies behind the bar.
Environment comb_room() {
  std::vector<Vec2> comb;
  const double t = 0.1, gap = 0.4;
  for (int i = 0; i < 7; ++i) {
    const double x = 1.0 + i * (t + gap);
    if (i > 0) comb.push_back({x, 1.2});
    comb.insert(comb.end(), {{x, 0.0}, {x + t, 0.0}});
    if (i < 6) comb.push_back({x + t, 1.2});
  }
  comb.insert(comb.end(), {{4.1, 1.35}, {1.0, 1.35}});
  return Environment({{0, -1.5}, {5.1, -1.5}, {5.1, 3}, {0, 3}}, {comb});
}
}  // namespace

TEST_CASE("TangentBug with a range sensor cuts round a comb's teeth a contact sensor walks into",
          "[tangent_bug]") {
  const Environment env = comb_room();
  const Vec2 start{2.3, -0.8}, goal{2.4, 2.2};
  const PlannerRun touch = go(env, start, goal, 0.0);
  REQUIRE(touch.status == PlanStatus::reached);
  for (double r : {2.0, kInfinity}) {
    INFO("range " << r);
    const PlannerRun run = go(env, start, goal, r);
    CHECK(run.status == PlanStatus::reached);
    CHECK(run.length <= (r == 2.0 ? 0.8 : 0.65) * touch.length);
  }
}

TEST_CASE("TangentBug follows a comb it sees from tooth to tooth, into one gap at most",
          "[tangent_bug]") {
  // A contact sensor walks into every gap on its way; a range sensor heads for the end of
  // the visible stretch of the comb, the next tooth's tip, and into no gap but where the
  // boundary following began.
  const Environment env = comb_room();
  for (double r : {0.0, 2.0, kInfinity}) {
    INFO("range " << r);
    const PlannerRun run = go(env, {2.3, -0.8}, {2.4, 2.2}, r);
    REQUIRE(run.status == PlanStatus::reached);
    std::set<int> gaps;  // gap i lies between x = 1.1 + 0.5 i and 1.5 + 0.5 i
    for (Vec2 p : run.path) {
      const double i = std::floor((p.x - 1.1) / 0.5);
      if (p.y > 0.1 && p.y < 1.2 && i >= 0 && i < 6 && p.x - 1.1 - 0.5 * i < 0.4)
        gaps.insert(static_cast<int>(i));
    }
    if (r == 0.0)
      CHECK(gaps.size() >= 3);
    else
      CHECK(gaps.size() <= 1);
  }
}

TEST_CASE("A recorded obstacle encloses what lies beyond it from the robot's side",
          "[tangent_bug]") {
  // Walked with free space on the left (+1) round a hole, the record runs clockwise.
  const RecordedObstacle hole({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 1, 1e-9);
  CHECK_FALSE(hole.outer());
  CHECK(hole.encloses({0.5, 0.5}));
  CHECK_FALSE(hole.encloses({1.5, 0.5}));
  CHECK_FALSE(hole.encloses({1.0, 0.5}));  // on it: reachable
  CHECK(hole.perimeter() == Approx(4.0));
  // The outer boundary, walked the other way (-1), encloses what lies outside it.
  const RecordedObstacle outer({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, -1, 1e-9);
  CHECK(outer.outer());
  CHECK(outer.encloses({1.5, 0.5}));
  CHECK_FALSE(outer.encloses({0.5, 0.5}));
  const RingPlace p = outer.closest({1.5, 0.25});
  CHECK(distance(p.point, Vec2{1, 0.25}) < 1e-12);
  const RingPlace q = outer.closest({0.5, -1.0});
  CHECK(outer.arc(q, p, 1) + outer.arc(q, p, -1) == Approx(4.0));
  CHECK(outer.arc(q, p, 1) == Approx(0.75));  // counter-clockwise: right, then up
}

TEST_CASE("TangentBug decides only on readings taken where it stands", "[tangent_bug]") {
  // A range sensor that reads every third step and loses a reading now and then, as the
  // controller's sampled sensor does: in between, the planner gets the last reading with its
  // own position and current contacts (the view is from where the reading was taken).
  const Environment env = test::room_with_cup();
  RandomStream noise(7, 0, "stale-readings");
  for (double range : {0.1, 0.5}) {
    for (Vec2 goal : {Vec2{2.05, 1.6}, Vec2{3.0, 1.15}, Vec2{3.0, 2.0}, Vec2{5.5, 3.5}}) {
      INFO("range " << range << ", goal (" << goal.x << ", " << goal.y << ")");
      TangentBugParams p = TangentBugParams::for_environment(env.diameter(), boundary_length(env));
      p.noise_margin = p.progress = 3.0 * 0.002;
      TangentBug bug(p);
      bug.set_goal(goal);
      Vec2 x{0.3, 0.3};
      SensorReading last;
      PlanStatus status = PlanStatus::moving;
      for (int k = 0; k < 20000 && status == PlanStatus::moving; ++k) {
        if (k == 0 || (k % 3 == 0 && !noise.bernoulli(0.3))) {
          last = sense(env, x, range);
          add_range_noise(last, noise, 0.002, env.tolerance());
        }
        SensorReading now = last;
        now.position = x;
        now.contacts = contacts_at(env, x);
        const PlanStep s = bug.step(now, 0.02);
        const Vec2 next = env.advance(x, s.next);
        REQUIRE(env.segment_inside(x, next));
        x = next;
        status = s.status;
      }
      if (env.contains(goal)) {
        CHECK(status == PlanStatus::reached);
      } else {
        CHECK(status == PlanStatus::projected);
        CHECK(distance(x, goal) <= distance(env.closest_point(goal), goal) + 6.0 * 0.002);
      }
    }
  }
}
