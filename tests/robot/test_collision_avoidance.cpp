// Collision avoidance between bodies (robots.avoidance): with ORCA no two bodies ever
// overlap and the paper's scenarios still converge; robots meeting head on in a corridor
// pass each other; the deadlock measures count robots blocked by each other.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "scenarios/scenario.hpp"
#include "scenarios/scenario_description.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/coverage_run.hpp"
#include "sim/simulation.hpp"
#include "tests/robot/paper_scenarios.hpp"

using namespace covsim;
using Catch::Matchers::Contains;
using covsim::test::paper;
using covsim::test::parse_beside_paper;

namespace {

// The least distance between two robots' centres and from a centre to ∂Ω, over every
// motion of every robot.
struct Distances final : CoverageObserver {
  std::shared_ptr<const Environment> env;
  std::vector<Vec2> at;
  double least_pair = INFINITY, least_wall = INFINITY;
  explicit Distances(const Scenario& s) : env(s.environment), at(s.robot_positions) {}
  void on_motion(SimTime, const Robot& r) override {
    at[r.id] = r.position;
    for (std::size_t j = 0; j < at.size(); ++j)
      if (j != r.id) least_pair = std::min(least_pair, distance(at[j], r.position));
    least_wall =
        std::min(least_wall, env->contains(r.position) ? env->boundary_distance(r.position)
                                                       : -env->boundary_distance(r.position));
  }
};

// A corridor 4 m long with two robots of radius 0.1 at its ends on its centre line.
nlohmann::json corridor(double bias, double width = 0.5) {
  const double y = width / 2;
  return {{"environment", {{"outer", {{0, 0}, {4, 0}, {4, width}, {0, width}}}}},
          {"density", {{"type", "uniform"}}},
          {"robots",
           {{"positions", {{0.5, y}, {3.5, y}}},
            {"radius", 0.1},
            {"avoidance", {{"type", "orca"}, {"bias", bias}}}}},
          {"controller", {{"type", "external"}}},
          {"convergence", {{"max_time", 200}}},
          {"seed", 1}};
}

// Two robots sent to targets in the corridor, their distances watched.
struct CorridorRun {
  Simulation sim;
  Distances d;
  CorridorRun(double width, Vec2 target0, Vec2 target1)
      : sim(parse_beside_paper(corridor(0.1, width), "corridor")), d(sim.scenario()) {
    sim.set_target(0, target0);
    sim.set_target(1, target1);
    sim.add_observer(&d);
  }
};

// A shipped scenario whose robots have bodies of this radius and ORCA between them.
nlohmann::json with_orca(const std::string& name, double radius) {
  nlohmann::json j = paper(name).json;
  j["robots"]["radius"] = radius;
  j["robots"]["avoidance"] = {{"type", "orca"}};
  return j;
}

}  // namespace

TEST_CASE("with ORCA no two bodies overlap and the runs converge", "[avoidance]") {
  for (const auto& [name, radius] : {std::pair{"u_shape.json", 0.02},
                                     {"office.json", 0.1},
                                     {"maze.json", 0.05},
                                     {"two_obstacles.json", 0.03},
                                     {"dead_ends.json", 0.05}}) {
    INFO(name);
    const Scenario s = parse_beside_paper(with_orca(name, radius), name);
    Distances d(s);
    const CoverageOutcome out = run_coverage(s, &d);
    CHECK(out.stop_reason == "converged");
    CHECK(out.contact_time == 0.0);
    CHECK(out.wall_contacts == 0);
    CHECK(out.body_gap_min >= -1e-12);
    CHECK(d.least_pair >= 2 * radius - 1e-12);
    CHECK(d.least_wall >= radius - 1e-9 * s.environment->diameter());
    // Robots still meet on the way (the start is crowded): the avoidance had work to do.
    CHECK(out.body_gap_min < radius);
  }
}

TEST_CASE("differential drives with ORCA converge without contact, dead ends too", "[avoidance]") {
  // In dead_ends three robots jam in a dead end: giving way in the first direction the walls
  // allow led nowhere (the other bodies were in it); the direction is chosen by the room the
  // walls and the bodies leave.
  for (const auto& [name, radius] : {std::pair{"u_shape.json", 0.02}, {"dead_ends.json", 0.05}}) {
    INFO(name);
    nlohmann::json j = with_orca(name, radius);
    j["robots"]["kinematics"] = {{"type", "differential_drive"}};
    const Scenario s = parse_beside_paper(j, name);
    Distances d(s);
    const CoverageOutcome out = run_coverage(s, &d);
    CHECK(out.stop_reason == "converged");
    CHECK(out.contact_time == 0.0);
    CHECK(d.least_pair >= 2 * radius - 1e-12);
    CHECK(out.deadlocks == out.deadlocks_resolved);
    CHECK(out.turn_time > 0.0);
  }
}

TEST_CASE("without avoidance the same bodies overlap", "[avoidance]") {
  // dead_ends' robots of 5 cm, as with ORCA above: some meet in the comb's gaps.
  nlohmann::json j = paper("dead_ends.json").json;
  j["robots"]["radius"] = 0.05;
  const CoverageOutcome out = run_coverage(parse_beside_paper(j, "dead_ends"));
  CHECK(out.contact_time > 0.0);
  CHECK(out.body_gap_min < 0.0);
  CHECK(out.deadlocks == 0);
}

TEST_CASE("robots meeting head on in a corridor pass each other", "[avoidance]") {
  for (const double width : {0.6, 0.8, 1.0}) {
    INFO("width " << width);
    CorridorRun run(width, {3.5, width / 2}, {0.5, width / 2});
    run.sim.run_until(SimTime::from_seconds(120));
    const CoverageOutcome out = run.sim.outcome();
    CHECK(distance(out.robots[0].position, {3.5, width / 2}) < 1e-9);
    CHECK(distance(out.robots[1].position, {0.5, width / 2}) < 1e-9);
    CHECK(run.d.least_pair >= 0.2 - 1e-12);
    CHECK(out.deadlocks == out.deadlocks_resolved);
    CHECK(out.deadlock_time < 5.0);
  }
}

TEST_CASE("a robot goes round one standing on its way", "[avoidance]") {
  // Robot 1 stops in the middle of a corridor 1 m wide; robot 0 passes it.
  CorridorRun run(1.0, {3.5, 0.5}, {2.0, 0.5});
  run.sim.run_until(SimTime::from_seconds(120));
  const CoverageOutcome out = run.sim.outcome();
  CHECK(distance(out.robots[0].position, {3.5, 0.5}) < 1e-9);
  CHECK(distance(out.robots[1].position, {2.0, 0.5}) < 1e-9);
  CHECK(run.d.least_pair >= 0.2 - 1e-12);
}

TEST_CASE("robots that cannot pass each other are counted as deadlocked", "[avoidance]") {
  // A corridor too narrow for two bodies side by side (0.3 m, bodies 0.2 m across): the
  // robot that gives way is pushed back, and neither ever gets past the other.
  CorridorRun run(0.3, {3.5, 0.15}, {0.5, 0.15});
  Simulation& jam = run.sim;
  double order = -INFINITY;  // the largest x0 - x1 seen
  for (int t = 1; t <= 100; ++t) {
    jam.run_until(SimTime::from_seconds(t));
    const auto& rs = jam.controller().robots();
    order = std::max(order, rs[0].position.x - rs[1].position.x);
  }
  const CoverageOutcome out = jam.outcome();
  CHECK(run.d.least_pair >= 0.2 - 1e-12);
  CHECK(order < 0.0);
  CHECK(out.deadlocks >= 2);
  CHECK(out.deadlock_time > 10.0);
  CHECK(jam.controller().give_ways() >= 1);
  CHECK(distance(out.robots[1].position, {0.5, 0.15}) > 2.0);
}

TEST_CASE("avoidance needs bodies, and a known type", "[avoidance]") {
  nlohmann::json j = paper("u_shape.json").json;
  j["robots"]["avoidance"] = {{"type", "orca"}};
  CHECK_THROWS_WITH(parse_beside_paper(j, "u_shape"),
                    Contains("$.robots.avoidance") && Contains("radius"));
  j["robots"]["radius"] = 0.02;
  j["robots"]["avoidance"] = {{"type", "rvo"}};
  CHECK_THROWS_WITH(parse_beside_paper(j, "u_shape"),
                    Contains("$.robots.avoidance") && Contains("orca"));
  j["robots"]["avoidance"] = {{"type", "orca"}, {"time_horizon", -1}};
  CHECK_THROWS_WITH(parse_beside_paper(j, "u_shape"), Contains("time_horizon"));
  j["robots"]["avoidance"] = {{"type", "orca"}, {"horizon", 1}};
  CHECK_THROWS_WITH(parse_beside_paper(j, "u_shape"), Contains("horizon"));
}

TEST_CASE("the scenario's description names the avoidance with every parameter", "[avoidance]") {
  nlohmann::json j = paper("u_shape.json").json;
  j["robots"]["radius"] = 0.02;
  j["robots"]["avoidance"] = {{"type", "orca"}};
  const auto out = describe_scenario(parse_beside_paper(j, "u_shape"));
  CHECK(out["robots"]["avoidance"]["type"] == "orca");
  CHECK(out["robots"]["avoidance"]["time_horizon"] == 2.0);
  CHECK(out["robots"]["avoidance"]["bias"] == 0.1);
  CHECK(out["robots"]["avoidance"]["range"].is_null());
  const auto plain = describe_scenario(paper("u_shape.json"));
  CHECK(plain["robots"]["avoidance"]["type"] == "none");
}
