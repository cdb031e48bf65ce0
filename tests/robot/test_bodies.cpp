// Robots with bodies (robots.radius): they plan, sense and move in Ω shrunk by the radius,
// their targets are projected onto the part of it they can reach, and the body measures count
// what they should.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "geometry/configuration_space.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/coverage_run.hpp"
#include "tests/robot/paper_scenarios.hpp"

using namespace covsim;
using Catch::Matchers::Contains;
using covsim::test::paper;
using covsim::test::parse_beside_paper;

namespace {

nlohmann::json scenario_json(const std::string& name) {
  return paper(name).json;
}

// Keeps the least distance from a robot's centre to ∂Ω over every motion step.
struct Clearance final : CoverageObserver {
  std::shared_ptr<const Environment> env;
  double least = INFINITY;
  std::size_t steps = 0;
  explicit Clearance(const Scenario& s) : env(s.environment) {}
  void on_motion(SimTime, const Robot& r) override {
    ++steps;
    least = std::min(least, env->contains(r.position) ? env->boundary_distance(r.position)
                                                      : -env->boundary_distance(r.position));
  }
};

// A square room [0, 1]² for two robots on the line y = 0.5.
nlohmann::json two_robots(double radius, double x0, double x1) {
  return {{"environment", {{"outer", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}}},
          {"density", {{"type", "uniform"}}},
          {"robots", {{"positions", {{x0, 0.5}, {x1, 0.5}}}, {"radius", radius}}},
          {"seed", 1}};
}

}  // namespace

TEST_CASE("bodies keep their radius from every wall and converge", "[bodies]") {
  for (const auto& [name, radius] : {std::pair{"u_shape.json", 0.02}, {"office.json", 0.1}}) {
    INFO(name);
    nlohmann::json j = scenario_json(name);
    j["robots"]["radius"] = radius;
    const Scenario s = parse_beside_paper(j, name);
    Clearance clearance(s);
    const CoverageOutcome out = run_coverage(s, &clearance);
    CHECK(out.stop_reason == "converged");
    CHECK(out.wall_contacts == 0);
    CHECK(out.radius == radius);
    CHECK(clearance.steps > 0);
    CHECK(clearance.least >= radius - 1e-9 * s.environment->diameter());
    CHECK(std::isfinite(out.body_gap_min));
  }
}

TEST_CASE("planners that plan on their map plan in the bodies' free space", "[bodies]") {
  // Built on Ω, they would aim at its corners, which the bodies cannot reach: the run would
  // not converge.
  for (const char* planner : {"visibility_graph", "grid_astar"}) {
    INFO(planner);
    nlohmann::json j = scenario_json("u_shape.json");
    j["robots"]["radius"] = 0.03;
    j["robots"]["positions"] = {{0.05, 0.9}, {0.12, 0.9}, {0.19, 0.9}, {0.05, 0.83}, {0.12, 0.83}};
    j["planner"] = {{"type", planner}};
    const Scenario s = parse_beside_paper(j, "u_shape.json");
    Clearance clearance(s);
    const CoverageOutcome out = run_coverage(s, &clearance);
    CHECK(out.stop_reason == "converged");
    CHECK(out.stalled_time == 0.0);
    CHECK(clearance.least >= 0.03 - 1e-9 * s.environment->diameter());
  }
}

TEST_CASE("with radius 0 the body measures stay empty", "[bodies]") {
  const CoverageOutcome out = run_coverage(paper("u_shape.json"));
  CHECK(std::isnan(out.body_gap_min));
  CHECK(out.contact_time == 0.0);
  CHECK(out.wall_contacts == 0);
}

TEST_CASE("a target beyond a passage too narrow for the body projects onto the robot's own part",
          "[bodies]") {
  // Two rooms joined by gaps of 0.15 m above and below a block: closed to bodies of radius
  // 0.1. Both robots start in the west room; Lloyd's cells cover the east room too.
  const nlohmann::json j = {{"environment",
                             {{"outer", {{0, 0}, {3, 0}, {3, 1}, {0, 1}}},
                              {"holes", {{{1, 0.15}, {2, 0.15}, {2, 0.85}, {1, 0.85}}}}}},
                            {"density", {{"type", "uniform"}}},
                            {"robots", {{"positions", {{0.3, 0.5}, {0.6, 0.5}}}, {"radius", 0.1}}},
                            {"seed", 1}};
  const Scenario s = parse_beside_paper(j, "two rooms");
  const ConfigurationSpace space(*s.environment, 0.1);
  REQUIRE(space.part_count() == 2);
  Clearance clearance(s);
  const CoverageOutcome out = run_coverage(s, &clearance);
  CHECK(out.stop_reason == "converged");
  const auto west = space.part_of({0.3, 0.5});
  bool beyond = false;
  for (const RobotOutcome& r : out.robots) {
    CHECK(space.part_of(r.position) == west);
    if (space.part_of(r.virtual_target) == west) continue;
    beyond = true;
    CHECK(r.projected);
    const Vec2 closest = space.part(*west).closest_point(r.virtual_target);
    CHECK(distance(r.real_target, closest) <= 1e-9);
    CHECK(distance(r.position, closest) <= 1e-3 * s.environment->diameter());
  }
  CHECK(beyond);  // the east room pulled a target through the closed passage
  CHECK(clearance.least >= 0.1 - 1e-9 * s.environment->diameter());
}

TEST_CASE("a body that overlaps a wall or another body at the start is refused", "[bodies]") {
  nlohmann::json j = scenario_json("u_shape.json");
  j["robots"]["radius"] = 0.05;  // robots 0.05 m apart in the file
  CHECK_THROWS_WITH(parse_beside_paper(j, "u_shape"),
                    Contains("positions[1]") && Contains("overlap"));
  CHECK_THROWS_WITH(parse_beside_paper(two_robots(0.1, 0.05, 0.5), "walls"),
                    Contains("positions[0]") && Contains("from a wall"));
  CHECK_THROWS_WITH(parse_beside_paper(two_robots(0.1, 0.45, 0.54), "bodies"),
                    Contains("positions[1]") && Contains("overlap"));
  CHECK_NOTHROW(parse_beside_paper(two_robots(0.05, 0.45, 0.55), "touching"));
  j["robots"]["radius"] = 0.6;  // u_shape is 1 m across
  CHECK_THROWS_WITH(parse_beside_paper(j, "u_shape"), Contains("fits nowhere"));
}

TEST_CASE("robots drawn with bodies fit the shrunk space and do not overlap", "[bodies]") {
  nlohmann::json j = scenario_json("office.json");
  j["robots"] = {{"count", 40},
                 {"start", {{"region", {{0.3, 4.0}, {3.2, 4.0}, {3.2, 6.0}, {0.3, 6.0}}}}},
                 {"radius", 0.12}};
  const Scenario s = parse_beside_paper(j, "office");
  const ConfigurationSpace space(*s.environment, 0.12);
  REQUIRE(s.robot_positions.size() == 40);
  for (std::size_t a = 0; a < s.robot_positions.size(); ++a) {
    CHECK(space.part_of(s.robot_positions[a]));
    for (std::size_t b = 0; b < a; ++b)
      CHECK(distance(s.robot_positions[a], s.robot_positions[b]) >= 0.24);
  }
}

TEST_CASE("the least gap and the contact time measure the bodies", "[bodies]") {
  // Apart by twice the radius (touching), the robots step 0.01 m apart each toward the
  // centroids of their halves: the least gap is at the first step, 0.02 m.
  const CoverageOutcome apart =
      run_coverage(parse_beside_paper(two_robots(0.05, 0.45, 0.55), "apart"));
  CHECK(apart.body_gap_min == Approx(0.02).margin(1e-12));
  CHECK(apart.contact_time == 0.0);
  // Overlapping by 0.04 m (set past the loader, as a program may): still overlapping after
  // the first step (0.08 m apart), touching after the second.
  Scenario s = parse_beside_paper(two_robots(0.05, 0.45, 0.55), "overlapping");
  s.robot_positions = {{0.47, 0.5}, {0.53, 0.5}};
  const CoverageOutcome overlapping = run_coverage(s);
  CHECK(overlapping.body_gap_min == Approx(-0.02).margin(1e-12));
  CHECK(overlapping.contact_time == Approx(0.2).margin(1e-12));
}
