// The belief layer (robot/belief_layer): with exact localization a robot believes where it
// is and Ω as it is; with odometry its belief drifts as it moves, the planner's frame follows
// the odometry, and the localization error is measured per loop-2 step; a robot that does not
// know Ω believes the map it has built.
#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/uniform_density.hpp"
#include "robot/belief_layer.hpp"
#include "robot/mapping.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

namespace {

// One robot in the unit square with a square obstacle [0.4, 0.6]², its body a point.
struct OneRobot {
  Kernel kernel{7};
  Environment env{square(0, 0, 1, 1), {square(0.4, 0.4, 0.6, 0.6)}};
  UniformDensity density;
  std::vector<Robot> robots = std::vector<Robot>(1);
  std::unique_ptr<BeliefLayer> belief;
  explicit OneRobot(const CoverageConfig& config, Vec2 start = {0.2, 0.2}) {
    robots[0].position = start;
    belief = std::make_unique<BeliefLayer>(
        kernel, env, density, std::vector<Vec2>{start}, config, 0.01, 1e-3,
        [this](std::uint32_t i) { return robots[i].position; },
        [this](std::uint32_t) -> const Environment& { return env; });
  }
  void move(Vec2 d) {
    Robot& r = robots[0];
    belief->moving(r, r.position + d, norm(d), kernel.now());
    r.position = r.position + d;
    belief->moved(r, d);
  }
};

}  // namespace

TEST_CASE("belief layer: with exact localization a robot believes what is", "[layers]") {
  OneRobot w{CoverageConfig{}};
  BeliefLayer& b = *w.belief;
  Robot& r = w.robots[0];
  CHECK(b.localization() == nullptr);
  CHECK(b.mapping() == nullptr);
  CHECK(b.known_position(r) == r.position);
  CHECK(b.planner_position(r) == r.position);
  CHECK(b.in_planner_frame(r, {0.9, 0.1}) == Vec2{0.9, 0.1});
  CHECK(&b.believed_free_space(r) == &w.env);
  CHECK(b.within_reach() == 1e-3);
  CHECK(b.reach(0.0) == 1e-3);
  CHECK(b.reach(0.01) == Approx(0.035));  // 3.5 standard deviations
  r.goal = {0.5, 0.5};                    // in the obstacle
  CHECK(b.goal_unreachable(r));
  r.goal = {0.9, 0.9};
  CHECK_FALSE(b.goal_unreachable(r));
  w.move({0.1, 0.0});
  b.tick(r);
  CHECK(b.localization_error_mean() == 0.0);
  CHECK(b.sensing().position_sigma == 0.0);
}

TEST_CASE("belief layer: an odometry drifts as the robot moves, and the planner works in it",
          "[layers]") {
  CoverageConfig config;
  config.localization.type = "odometry";
  config.localization.params.set("drift", 0.05);
  OneRobot w{config};
  BeliefLayer& b = *w.belief;
  Robot& r = w.robots[0];
  REQUIRE(b.localization() != nullptr);
  CHECK(b.sensing().position_sigma > 0.0);  // the planners are told the odometry's jitter
  CHECK(b.within_reach() >= 1e-3);
  for (int k = 0; k < 50; ++k)
    w.move({0.0, 0.01});
  const Vec2 odometry = b.planner_position(r);
  CHECK(odometry != r.position);  // drifted over 0.5 m
  CHECK(distance(odometry, r.position) < 0.2);
  b.tick(r);
  CHECK(b.localization_error_mean() == Approx(distance(b.known_position(r), r.position)));
  CHECK(b.localization_error_max() == b.localization_error_mean());
  // Without fixes, the estimate is the odometry: goals keep their place in the planner's
  // frame.
  CHECK(b.in_planner_frame(r, {0.9, 0.9}) == Vec2{0.9, 0.9});
}

TEST_CASE("belief layer: a robot that does not know Ω believes the map it has built", "[layers]") {
  CoverageConfig config;
  config.mapping.known = KnownEnvironment::none;
  config.mapping.compare_known = false;
  config.sensor.range = 0.15;
  OneRobot w{config, {0.1, 0.1}};
  BeliefLayer& b = *w.belief;
  Robot& r = w.robots[0];
  REQUIRE(b.mapping() != nullptr);
  b.start(SimTime{}, w.robots);
  const Environment& believed = b.believed_free_space(r);
  CHECK(&believed != &w.env);
  // The obstacle was not seen from the corner: the robot believes its middle free.
  CHECK(believed.contains({0.5, 0.5}));
  CHECK_FALSE(w.env.contains({0.5, 0.5}));
  // A goal settled for where the map shows free space is a discovery.
  r.goal = {0.5, 0.5};
  b.arrived(r, PlanStatus::projected, SimTime{});
  CHECK(b.discoveries() == 1);
}

TEST_CASE(
    "belief layer: a map planner beside a tracking system plans from the estimate, "
    "on the map inflated by its error",
    "[layers]") {
  CoverageConfig config;
  config.planner.type = "grid_astar";
  config.localization.type = "tracking";
  config.localization.params.set("noise", 0.005);
  OneRobot w{config};
  BeliefLayer& b = *w.belief;
  Robot& r = w.robots[0];
  REQUIRE(b.map_frame());
  // Three standard deviations of a fix's noise (no drift between fixes).
  CHECK(b.inflation() == Approx(0.015));
  CHECK(b.within_reach() >= b.inflation());
  CHECK(b.planner_reach() == b.within_reach());
  // Ω's frame: goals as they are, the planner at the estimate.
  CHECK(b.in_planner_frame(r, {0.9, 0.1}) == Vec2{0.9, 0.1});
  CHECK(b.planner_position(r) == b.known_position(r));
  // A goal nearer a wall than the inflation is one the planner cannot reach.
  r.planner_goal = {0.9, 0.99};
  CHECK(b.goal_unreachable(r));
  r.planner_goal = {0.9, 0.9};
  CHECK_FALSE(b.goal_unreachable(r));
  // TangentBug beside the same tracking system works in the odometry's frame, uninflated.
  config.planner.type = "tangent_bug";
  OneRobot t{config};
  CHECK_FALSE(t.belief->map_frame());
  CHECK(t.belief->inflation() == 0.0);
}
