// Whole runs with bodies that have a heading (robots.kinematics): every motion step keeps the
// speed, turn rate, acceleration and wheel limits, the body drives along its heading, the
// runs converge, and turning costs time.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>

#include "scenarios/scenario.hpp"
#include "sim/coverage_run.hpp"
#include "tests/robot/paper_scenarios.hpp"

using namespace covsim;
using Catch::Matchers::Contains;
using covsim::test::paper;

namespace {

Scenario u_shape_with(const nlohmann::json& kinematics) {
  nlohmann::json j = paper("u_shape.json").json;
  j["robots"]["kinematics"] = kinematics;
  return covsim::test::parse_beside_paper(j, "u_shape");
}

// Checks every motion step of every robot against the limits.
struct LimitCheck final : CoverageObserver {
  double dt, speed, turn_rate, acceleration, angular_acceleration, wheel_base;
  std::map<std::uint32_t, std::pair<Vec2, BodyState>> last;
  std::size_t steps = 0, turning = 0, worst = 0;
  void on_motion(SimTime, const Robot& r) override {
    const auto it = last.find(r.id);
    if (it != last.end()) {
      const auto& [p, s] = it->second;
      const double moved = distance(p, r.position);
      const double turned =
          std::fabs(std::remainder(r.body.heading - s.heading, 2 * std::numbers::pi));
      bool ok = moved <= speed * dt * (1 + 1e-9) && turned <= turn_rate * dt * (1 + 1e-9) &&
                r.body.speed <= speed * (1 + 1e-12) &&
                std::fabs(r.body.turn_rate) <= turn_rate * (1 + 1e-12) &&
                std::fabs(r.body.speed - s.speed) <= acceleration * dt * (1 + 1e-9) + 1e-12 &&
                std::fabs(r.body.turn_rate - s.turn_rate) <=
                    angular_acceleration * dt * (1 + 1e-9) + 1e-12;
      // The body drives along its heading (it turned first, in place). The way's direction
      // is only as exact as the rounding of its ends' coordinates over its length (a step of
      // 1e-8 m to a vertex: 1e-8 rad).
      if (moved > 1e-12) {
        const Vec2 d = r.position - p;
        const double rounding = 4e-16 * (1.0 + norm(p)) / moved;
        ok = ok && std::fabs(std::remainder(std::atan2(d.y, d.x) - r.body.heading,
                                            2 * std::numbers::pi)) <= 1e-9 + rounding;
      } else if (turned > 0.0) {
        ++turning;
      }
      // Each wheel within the top speed: the body's speed, or half the wheel base times the
      // turn rate.
      if (wheel_base > 0.0)
        ok = ok && std::fabs(r.body.turn_rate) * wheel_base / 2 <= speed * (1 + 1e-12);
      if (!ok) ++worst;
      ++steps;
    }
    last[r.id] = {r.position, r.body};
  }
};

}  // namespace

TEST_CASE("unicycles and differential drives keep their limits and converge", "[kinematics]") {
  SECTION("unicycle") {
    const Scenario s = u_shape_with({{"type", "unicycle"},
                                     {"turn_rate", 2.0},
                                     {"acceleration", 0.5},
                                     {"angular_acceleration", 4.0}});
    LimitCheck check{};
    check.dt = 0.1;
    check.speed = s.coverage.max_speed;
    check.turn_rate = 2.0;
    check.acceleration = 0.5;
    check.angular_acceleration = 4.0;
    const CoverageOutcome out = run_coverage(s, &check);
    CHECK(out.stop_reason == "converged");
    CHECK(check.steps > 100);
    CHECK(check.turning > 0);
    CHECK(check.worst == 0);
    CHECK(out.turn_time > 0.0);
    CHECK(out.hard_stops == 0);
  }
  SECTION("differential drive") {
    const Scenario s = u_shape_with(
        {{"type", "differential_drive"}, {"wheel_base", 0.053}, {"wheel_acceleration", 0.5}});
    LimitCheck check{};
    check.dt = 0.1;
    check.speed = s.coverage.max_speed;
    check.turn_rate = 2 * s.coverage.max_speed / 0.053;
    check.acceleration = 0.5;
    check.angular_acceleration = 2 * 0.5 / 0.053;
    check.wheel_base = 0.053;
    const CoverageOutcome out = run_coverage(s, &check);
    CHECK(out.stop_reason == "converged");
    CHECK(check.turning > 0);
    CHECK(check.worst == 0);
    CHECK(out.hard_stops == 0);
  }
}

TEST_CASE("turning costs time: the slower the turn, the later the run ends", "[kinematics]") {
  const CoverageOutcome point = run_coverage(paper("u_shape.json"));
  const CoverageOutcome quick =
      run_coverage(u_shape_with({{"type", "unicycle"}, {"turn_rate", 20.0}}));
  const CoverageOutcome slow =
      run_coverage(u_shape_with({{"type", "unicycle"}, {"turn_rate", 0.5}}));
  REQUIRE(point.stop_reason == "converged");
  REQUIRE(quick.stop_reason == "converged");
  REQUIRE(slow.stop_reason == "converged");
  CHECK(point.turn_time == 0.0);
  CHECK(slow.turn_time > 4 * quick.turn_time);
  CHECK(slow.sim_time > quick.sim_time);
  // The same planner paths, carried out more slowly: the final costs agree.
  CHECK(slow.cost_real == Approx(point.cost_real).epsilon(0.02));
}

TEST_CASE("a kinematics is named, and its parameters checked", "[kinematics]") {
  CHECK_THROWS_WITH(u_shape_with({{"type", "tricycle"}}),
                    Contains("$.robots.kinematics") && Contains("differential_drive"));
  CHECK_THROWS_WITH(u_shape_with({{"type", "differential_drive"}, {"wheel_base", -1}}),
                    Contains("wheel_base"));
  CHECK_THROWS_WITH(u_shape_with({{"type", "unicycle"}, {"wheel_base", 0.05}}),
                    Contains("wheel_base"));
}
