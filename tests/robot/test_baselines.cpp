#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/visibility_graph.hpp"
#include "net/bernoulli_loss.hpp"
#include "planners/planner_registry.hpp"
#include "robot/coverage_law_registry.hpp"
#include "scenarios/scenario.hpp"
#include "sim/coverage_run.hpp"
#include "tests/robot/paper_scenarios.hpp"

using namespace covsim;
using covsim::test::MotionChecker;
using covsim::test::paper;

namespace {
// A coverage law by name, with the given lattice spacing if it integrates on a lattice.
LawConfig law(const std::string& type, std::optional<double> resolution = std::nullopt) {
  LawConfig c;
  c.type = type;
  if (resolution && find_param(coverage_law_registry().at(type).params, "resolution") != nullptr)
    c.params.set("resolution", *resolution);
  return c;
}

// The registered laws that compute their own targets (not a driving program's).
std::vector<std::string> autonomous_laws() {
  std::vector<std::string> out;
  for (const LawEntry& e : coverage_law_registry().entries()) {
    if (e.autonomous) out.push_back(e.name);
  }
  return out;
}

// The registered planners that keep the robot in Ω, and of those the complete ones.
std::vector<std::string> planners(bool complete_only) {
  const Environment square({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {});
  std::vector<std::string> out;
  for (const PlannerEntry& e : planner_registry().entries()) {
    if (make_planner(e.name, square)->avoids_obstacles() && (e.contract.complete || !complete_only))
      out.push_back(e.name);
  }
  return out;
}
}  // namespace

namespace {

CoverageOutcome run(const Scenario& s) {
  MotionChecker checker(s);
  CoverageOutcome out = run_coverage(s, &checker);
  CHECK(checker.outside == 0);
  return out;
}

// The uniform geodesic cost ½ ∫ d_g(p, x)² over Ω, by exact shortest paths to the points
// of a lattice of spacing h: independent of the controller's lattice and trees.
double geodesic_cost(const VisibilityGraph& g, Vec2 p, double h) {
  const Environment& env = g.environment();
  double sum = 0.0;
  for (double x = h / 2; x < env.bounds().hi.x; x += h) {
    for (double y = h / 2; y < env.bounds().hi.y; y += h) {
      if (!env.contains({x, y})) continue;
      const double d = g.shortest_path(p, {x, y}).length;
      sum += 0.5 * d * d * h * h;
    }
  }
  return sum;
}
}  // namespace

TEST_CASE("geodesic Lloyd settles at the compromise point of Fig. 2b", "[baseline]") {
  Scenario s = paper("fig2b.json");
  s.coverage.law = law("geodesic_lloyd", 0.005);
  s.coverage.position_tolerance = 1e-4;
  s.coverage.planner.type = "visibility_graph";
  const CoverageOutcome out = run(s);
  REQUIRE(out.converged);
  const Vec2 p = out.robots[0].position;
  // The brute-force minimiser of the geodesic cost on the U's axis of symmetry.
  const VisibilityGraph g(*s.environment);
  double best_y = 0.0, best = INFINITY;
  for (double y = 0.25; y < 0.3451; y += 0.0025) {
    const double c = geodesic_cost(g, {0.5, y}, 0.01);
    if (c < best) best = c, best_y = y;
  }
  INFO("final (" << p.x << ", " << p.y << "), brute-force minimum at y = " << best_y);
  CHECK(std::abs(p.x - 0.5) < 0.005);
  CHECK(std::abs(p.y - best_y) < 0.005);
  // A compromise short of the notch: inside Ω, below the projection of the centroid
  // (0.5, 0.35) and far from the Euclidean centroid (0.5, 0.4576) in the obstacle.
  CHECK(best_y < 0.335);
  CHECK(distance(p, {0.5, 0.4576}) > 0.13);
  CHECK(out.robots[0].status == PlanStatus::reached);
  CHECK(out.target_outside_steps == 0);
}

TEST_CASE("geodesic Lloyd without a planner drives out of Ω on Fig. 2d", "[baseline]") {
  // The paper's Fig. 2d: the gradient sum does not vanish at the boundary, and nothing keeps
  // the robot in Ω. The run ends where the robot crosses ∂Ω, with the time and the goal.
  Scenario s = paper("fig2d.json");
  s.coverage.law = law("geodesic_lloyd");
  s.coverage.planner.type = "none";
  const CoverageOutcome out = run(s);
  CHECK(out.stop_reason == "left_environment");
  CHECK_FALSE(out.converged);
  REQUIRE(out.left_environment);
  const LeftEnvironment& left = *out.left_environment;
  CHECK(left.robot == 0);
  CHECK(left.time.seconds() > 1.0);
  CHECK(left.time == out.sim_time);
  // Round the L's inner corner (0.3, 0.3), onto the top of the lower arm, toward a goal
  // beyond it, in the obstacle.
  CHECK(left.position.y == Approx(0.3).margin(1e-9));
  CHECK(left.position.x > 0.3);
  CHECK(left.position.x < 0.33);
  CHECK_FALSE(s.environment->edges_at(left.position).empty());
  CHECK_FALSE(s.environment->contains(left.goal));
  CHECK(out.robots[0].position == left.position);
  // Same scenario, same incident; the paper's controller with TangentBug stays in Ω.
  CHECK(run_coverage(s).fingerprint == out.fingerprint);
  const CoverageOutcome paper_run = run(paper("fig2d.json"));
  CHECK(paper_run.converged);
  CHECK_FALSE(paper_run.left_environment);
}

TEST_CASE("a motion into an obstacle is a departure, a corner grazed on the way is not",
          "[baseline]") {
  // office's steps (1 cm) are shorter than its tolerance (5 cm): a robot driving into a wall
  // still leaves Ω, though no single step cuts deeper than the tolerance.
  Scenario office = paper("office.json");
  office.coverage.planner.type = "none";
  office.coverage.max_time = SimTime::from_seconds(60.0);
  CHECK(run_coverage(office).stop_reason == "left_environment");
  // Small geodesic steps round the corners of fig2b and fig2d cut them by micrometres on the
  // way to targets in Ω: no departure.
  for (const char* name : {"fig2b.json", "fig2d.json"}) {
    INFO(name);
    Scenario s = paper(name);
    s.coverage.law = law("geodesic_lloyd");
    s.coverage.law.params.set("gain", 0.05);
    s.coverage.planner.type = "none";
    const CoverageOutcome out = run_coverage(s);
    CHECK(out.converged);
    CHECK_FALSE(out.left_environment);
  }
}

TEST_CASE("geodesic Lloyd without a planner stops in front of the obstacle on Fig. 2c",
          "[baseline]") {
  // Fig. 2c: started on the box's axis of symmetry, facing its right side, the compromise
  // between the ways round above and below it holds the robot in front of that side; the
  // paper's controller sends it round to the projection of the centroid on the far side,
  // which costs less.
  Scenario s = paper("fig2c.json");
  s.robot_positions = {{0.9, 0.5}};
  s.coverage.law = law("geodesic_lloyd");
  s.coverage.planner.type = "none";
  const CoverageOutcome geodesic = run(s);
  CHECK(geodesic.converged);
  const Vec2 p = geodesic.robots[0].position;
  INFO("final (" << p.x << ", " << p.y << ")");
  CHECK(p.x > 0.6);
  CHECK(p.x < 0.65);
  CHECK(std::abs(p.y - 0.5) < 0.01);
  Scenario method = paper("fig2c.json");
  method.robot_positions = {{0.9, 0.5}};
  const CoverageOutcome ours = run(method);
  CHECK(ours.converged);
  CHECK(distance(ours.robots[0].position, Vec2{0.42, 0.5}) < 2e-3);
  CHECK(ours.cost_real < geodesic.cost_real);
}

TEST_CASE("Lloyd on real positions with straight-line motion gets stuck on Fig. 2c", "[baseline]") {
  Scenario s = paper("fig2c.json");
  s.coverage.law = law("euclidean_lloyd");
  s.coverage.planner.type = "straight_line";
  const CoverageOutcome stuck = run(s);
  CHECK_FALSE(stuck.converged);
  CHECK(stuck.stop_reason == "stuck");
  const RobotOutcome& r = stuck.robots[0];
  CHECK(r.status == PlanStatus::stalled);
  // Against the obstacle, short of the projection of its target.
  CHECK_FALSE(s.environment->edges_at(r.position).empty());
  CHECK(distance(r.position, r.real_target) > 0.1);
  CHECK(r.target_outside_steps > 0);
  CHECK(r.stalled_time > 0.0);
  CHECK(r.centroid_distance > 0.1);

  // The paper's controller with TangentBug converges, at the projection.
  const CoverageOutcome ok = run(paper("fig2c.json"));
  CHECK(ok.converged);
  CHECK(ok.stop_reason == "converged");
  CHECK(ok.robots[0].projected);
  CHECK(distance(ok.robots[0].position, ok.robots[0].real_target) < 1e-3);
  CHECK(ok.cost_real < stuck.cost_real);
}

TEST_CASE("a planner that stalls short of a target outside Ω is sent to its projection",
          "[baseline]") {
  // Straight at the centroid inside the hole, from the left: the wall stops the robot at
  // the projection itself, which it then reaches.
  Scenario s = paper("fig2c.json");
  s.robot_positions = {{0.1, 0.5}};
  s.coverage.planner.type = "straight_line";
  const CoverageOutcome out = run(s);
  CHECK(out.converged);
  CHECK(out.robots[0].status == PlanStatus::reached);
  CHECK(out.robots[0].projected);
  CHECK(distance(out.robots[0].position, Vec2{0.42, 0.5}) < 1e-9);
  CHECK(out.stalled_time > 0.0);
}

TEST_CASE("Euclidean Lloyd with a complete planner ends at the centroids", "[baseline]") {
  const std::vector<std::string> complete = planners(true);
  CHECK(complete.size() >= 3);  // tangent_bug, grid_astar, visibility_graph
  for (const std::string& planner : complete) {
    Scenario s = paper("l_shape.json");
    s.coverage.law = law("euclidean_lloyd");
    s.coverage.planner.type = planner;
    const CoverageOutcome out = run(s);
    INFO(planner);
    CHECK(out.converged);
    CHECK(out.centroid_distance_max < 2e-3 * s.environment->diameter());
    CHECK(out.stalled_time == 0.0);
  }
}

TEST_CASE("every planner and controller runs the paper's scenarios inside Ω and ends",
          "[baseline]") {
  // Every registered law that sets its own targets, with every planner that avoids
  // obstacles (`none` leaves Ω by design: the departures are tested above).
  const std::vector<std::string> laws = autonomous_laws(), all = planners(false);
  CHECK(laws.size() >= 3);
  CHECK(all.size() >= 5);
  for (const char* name : {"l_shape.json", "two_obstacles.json", "fig2d.json"}) {
    for (const std::string& k : laws) {
      for (const std::string& planner : all) {
        Scenario s = paper(name);
        s.coverage.law = law(k, s.environment->diameter() / 40.0);
        s.coverage.planner.type = planner;
        s.coverage.max_time = SimTime::from_seconds(30.0);
        INFO(name << " " << k << " " << planner);
        const CoverageOutcome out = run(s);
        CHECK((out.stop_reason == "converged" || out.stop_reason == "stuck" ||
               out.stop_reason == "max_time"));
        // Same scenario, same fingerprint.
        CHECK(run_coverage(s).fingerprint == out.fingerprint);
      }
    }
  }
}

TEST_CASE("the baselines run decentralized, from what each robot hears", "[baseline]") {
  // Every autonomous law but the paper's (the default), whose networked runs are tested with
  // the network.
  for (const std::string& k : autonomous_laws()) {
    if (k == LawConfig{}.type) continue;
    Scenario s = paper("u_shape.json");
    s.coverage.law = law(k, s.environment->diameter() / 50.0);
    s.coverage.network.channel.loss = std::make_shared<const BernoulliLoss>(0.3);
    INFO(k);
    const CoverageOutcome out = run(s);
    CHECK(out.decentralized);
    CHECK(out.network.lost > 0);
    CHECK(out.converged);
    CHECK(run_coverage(s).fingerprint == out.fingerprint);
    // A different seed draws different losses, and so a different run.
    s.seed = *s.seed + 1;
    CHECK(run_coverage(s).fingerprint != out.fingerprint);
  }
}
