// The planning layer (robot/planning_layer): the goals it hands a planner, the steps it takes
// from it (checked: finite, no longer than the step length; carried out from the real
// position when the planner works in a drifting odometry's frame), and the walls neighbours
// share, with a scripted planner.
#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/scan.hpp"
#include "geometry/uniform_density.hpp"
#include "robot/component_error.hpp"
#include "robot/planning_layer.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using Catch::Matchers::Contains;
using covsim::test::square;

namespace {

// Records what it is told; proposes `next` with `status`.
struct Scripted final : Planner {
  std::vector<Vec2> goals, moved_goals;
  std::vector<SensedPiece> walls;
  Vec2 seen_from{NAN, NAN};
  Vec2 next;
  PlanStatus status = PlanStatus::moving;
  std::string_view name() const override { return "scripted"; }
  void set_goal(Vec2 g) override { goals.push_back(g); }
  void move_goal(Vec2 g) override { moved_goals.push_back(g); }
  PlanStep step(const SensorReading& r, double) override {
    seen_from = r.position;
    return PlanStep{next, status};
  }
  void learn(const std::vector<SensedPiece>& w) override { walls = w; }
};

struct Layers {
  Kernel kernel{3};
  Environment env{square(0, 0, 1, 1), {}};
  UniformDensity density;
  ConfigurationSpace space{env, 0.0};
  std::vector<std::size_t> part{0};
  PlannerSpace planners{env, space, 0.0, 0.0, 3.0};
  std::vector<Robot> robots = std::vector<Robot>(1);
  std::unique_ptr<BeliefLayer> belief;
  std::unique_ptr<SensorModel> sensor;
  std::unique_ptr<PlanningLayer> planning;
  Scripted* planner = nullptr;
  explicit Layers(const CoverageConfig& config) {
    robots[0].position = {0.5, 0.5};
    auto p = std::make_unique<Scripted>();
    planner = p.get();
    robots[0].planner = std::move(p);
    const auto at = [this](std::uint32_t i) { return robots[i].position; };
    const auto space_of = [this](std::uint32_t) -> const Environment& { return env; };
    belief = std::make_unique<BeliefLayer>(kernel, env, density, std::vector<Vec2>{{0.5, 0.5}},
                                           config, 0.01, 1e-3, at, space_of);
    sensor = std::make_unique<SensorModel>(kernel, space_of, config.sensor, 1, at);
    planners.add({0.5, 0.5}, 0);
    planning =
        std::make_unique<PlanningLayer>(kernel, *belief, *sensor, 0.01, 0.0, space, part, planners);
  }
};

}  // namespace

TEST_CASE("planning layer: goals, and steps checked before they are taken", "[layers]") {
  Layers w{CoverageConfig{}};
  Robot& r = w.robots[0];
  r.status = PlanStatus::reached;
  w.planning->set_goal(r, {0.8, 0.5});
  CHECK(r.goal == Vec2{0.8, 0.5});
  CHECK(r.planner_goal == Vec2{0.8, 0.5});
  CHECK(r.status == PlanStatus::moving);
  CHECK(w.planner->goals == std::vector<Vec2>{{0.8, 0.5}});
  w.planning->move_goal(r, {0.8, 0.6});
  CHECK(w.planner->moved_goals == std::vector<Vec2>{{0.8, 0.6}});
  CHECK(r.goal == Vec2{0.8, 0.6});
  // A step of the step length is taken as proposed, from the reading where the robot is.
  w.planner->next = {0.51, 0.5};
  const PlanStep s = w.planning->step(r);
  CHECK(s.next == Vec2{0.51, 0.5});
  CHECK(w.planner->seen_from == r.position);
  // Longer: an error naming the robot, the planner and the step.
  w.planner->next = {0.6, 0.5};
  CHECK_THROWS_WITH(w.planning->step(r), Contains("robot 0's planner scripted proposed a step"));
  // Not finite: the planner's own error, with the robot and the time.
  w.planner->next = {NAN, 0.5};
  try {
    w.planning->step(r);
    FAIL("a step that is not finite was taken");
  } catch (const ComponentError& e) {
    CHECK_THAT(e.context(), Contains("robot 0's planner \"scripted\" at t = 0 s"));
    CHECK_THAT(std::string(e.what()), Contains("a step must be a finite point"));
  }
}

TEST_CASE(
    "planning layer: in a drifting odometry's frame, the step is carried out from the "
    "real position",
    "[layers]") {
  CoverageConfig config;
  config.localization.type = "odometry";
  config.localization.params.set("drift", 0.05);
  Layers w{config};
  Robot& r = w.robots[0];
  for (int k = 0; k < 30; ++k) {
    r.position = r.position + Vec2{0.01, 0.0};
    w.belief->moved(r, {0.01, 0.0});
  }
  const Vec2 odometry = w.belief->planner_position(r);
  REQUIRE(odometry != r.position);
  w.planner->next = odometry + Vec2{0.0, 0.01};
  const PlanStep s = w.planning->step(r);
  CHECK(w.planner->seen_from == odometry);  // the reading as the robot maps it
  CHECK(s.next.x == Approx(r.position.x));
  CHECK(s.next.y == Approx(r.position.y + 0.01));
}

TEST_CASE("planning layer: a neighbour's walls reach the planner", "[layers]") {
  Layers w{CoverageConfig{}};
  Scan scan;
  scan.origin = {0.2, 0.2};
  scan.range = 1.0;
  scan.pieces.push_back(VisiblePiece{{1, 0}, {1, 1}, 1});
  w.planning->learn(w.robots[0], scan);
  REQUIRE(w.planner->walls.size() == 1);
  CHECK(w.planner->walls[0].a == Vec2{1, 0});
  CHECK(w.planner->walls[0].b == Vec2{1, 1});
}
