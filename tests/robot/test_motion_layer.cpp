// The motion layer (robot/motion_layer): without kinematics or avoidance a planner's step is
// the motion; a unicycle follows it as a waypoint over several motion steps and arrives
// exactly; under ORCA two bodies driving at each other never come nearer than touching.
#include <catch2/catch.hpp>

#include <cmath>

#include "robot/motion_layer.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

namespace {

struct Motion {
  Kernel kernel{5};
  Environment env{square(0, 0, 2, 2), {}};
  CoverageConfig config;
  std::vector<Robot> robots;
  std::vector<std::pair<std::uint32_t, PlanStatus>> arrivals;
  std::size_t moves = 0;
  std::unique_ptr<MotionLayer> motion;
  Motion(CoverageConfig c, std::vector<Vec2> at) : config(std::move(c)), robots(at.size()) {
    for (std::uint32_t i = 0; i < at.size(); ++i) {
      robots[i].id = i;
      robots[i].position = at[i];
    }
    motion = std::make_unique<MotionLayer>(
        kernel, env, config, robots,
        MotionHost{[this](Robot& r, Vec2 p) {
                     ++moves;
                     r.position = p;
                     motion->moved(r, p);
                   },
                   [this](Robot& r, PlanStatus s) {
                     arrivals.emplace_back(r.id, s);
                     r.status = s;
                     return true;
                   },
                   [](Robot&) {}, [this](std::uint32_t) -> const Environment& { return env; }});
  }
  void give(std::uint32_t i, Vec2 to, PlanStatus s) {
    robots[i].waypoint = PlanStep{to, s};
    robots[i].waypoint_from = robots[i].position;
  }
};

}  // namespace

TEST_CASE("motion layer: a planner's step is the motion without kinematics or avoidance",
          "[layers]") {
  Motion m{CoverageConfig{}, {{0.5, 0.5}}};
  CHECK_FALSE(m.motion->follows_waypoints());
  CHECK_FALSE(m.motion->avoids_collisions());
}

TEST_CASE("motion layer: a unicycle follows its waypoint over motion steps and arrives exactly",
          "[layers]") {
  CoverageConfig c;
  c.kinematics.type = "unicycle";
  c.max_speed = 0.1;
  Motion m{c, {{0.5, 0.5}}};
  REQUIRE(m.motion->follows_waypoints());
  Robot& r = m.robots[0];
  m.give(0, {0.5, 0.51}, PlanStatus::reached);  // behind its heading (+x): it turns first
  int steps = 0;
  while (r.waypoint && steps < 1000) {
    REQUIRE(m.motion->follow_waypoint(r));
    ++steps;
  }
  CHECK(steps > 1);
  CHECK(r.position == Vec2{0.5, 0.51});
  REQUIRE(m.arrivals.size() == 1);
  CHECK(m.arrivals[0].second == PlanStatus::reached);
  CHECK(m.motion->turn_time() > 0.0);
}

TEST_CASE("motion layer: under ORCA two bodies driving at each other never overlap", "[layers]") {
  CoverageConfig c;
  c.radius = 0.05;
  c.avoidance.type = "orca";
  c.max_speed = 0.1;
  Motion m{c, {{0.5, 1.0}, {1.5, 1.0}}};
  REQUIRE(m.motion->avoids_collisions());
  double least = INFINITY;
  for (int t = 0; t < 400; ++t) {
    for (Robot& r : m.robots) {
      if (!r.waypoint) {
        // A step of the step length toward the other's start, as a planner would propose.
        const Vec2 goal = r.id == 0 ? Vec2{1.5, 1.0} : Vec2{0.5, 1.0};
        const Vec2 d = goal - r.position;
        if (norm(d) < 1e-9) continue;
        const double len = std::min(norm(d), c.max_speed * c.loop2_period.seconds());
        m.give(r.id, r.position + (len / norm(d)) * d,
               len == norm(d) ? PlanStatus::reached : PlanStatus::moving);
      }
      const Vec2 before = r.position;
      REQUIRE(m.motion->follow_waypoint(r));
      r.velocity = (r.position - before) / c.loop2_period.seconds();
    }
    least = std::min(least, distance(m.robots[0].position, m.robots[1].position));
  }
  CHECK(least >= 2 * c.radius - 1e-9);
  // And got by each other (ORCA's bias passes on the right).
  INFO(m.robots[0].position.x << ", " << m.robots[1].position.x);
  CHECK(m.robots[0].position.x > 1.2);
  CHECK(m.robots[1].position.x < 0.8);
}
