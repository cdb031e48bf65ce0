// The small linear program of reciprocal collision avoidance: the velocity in a disk nearest
// a preferred one, on the permitted side of half-planes, or the least worst violation.
#include <catch2/catch.hpp>

#include <cmath>

#include "geometry/velocity_program.hpp"

using namespace covsim;

namespace {

// The velocities with x >= a (the left of a line heading down).
VelocityConstraint at_least_x(double a) {
  return VelocityConstraint{{a, 0.0}, {0.0, -1.0}};
}
VelocityConstraint at_most_x(double a) {
  return VelocityConstraint{{a, 0.0}, {0.0, 1.0}};
}
VelocityConstraint at_least_y(double a) {
  return VelocityConstraint{{0.0, a}, {1.0, 0.0}};
}

}  // namespace

TEST_CASE("a permitted preferred velocity is returned as it is", "[velocity_program]") {
  const VelocityChoice c = closest_permitted_velocity({at_least_x(-1.0)}, 2.0, {0.3, 0.4});
  CHECK(c.feasible);
  CHECK(c.velocity == Vec2{0.3, 0.4});
}

TEST_CASE("without constraints, the preferred velocity is cut to the top speed",
          "[velocity_program]") {
  const VelocityChoice c = closest_permitted_velocity({}, 1.0, {3.0, 4.0});
  CHECK(c.velocity.x == Approx(0.6));
  CHECK(c.velocity.y == Approx(0.8));
}

TEST_CASE("one half-plane: the projection onto its line", "[velocity_program]") {
  const VelocityChoice c = closest_permitted_velocity({at_least_x(0.5)}, 2.0, {0.0, 1.0});
  CHECK(c.feasible);
  CHECK(c.velocity.x == Approx(0.5));
  CHECK(c.velocity.y == Approx(1.0));
}

TEST_CASE("two half-planes: the corner when it is nearest", "[velocity_program]") {
  const VelocityChoice c =
      closest_permitted_velocity({at_least_x(0.5), at_least_y(0.25)}, 2.0, {0.0, 0.0});
  CHECK(c.feasible);
  CHECK(c.velocity.x == Approx(0.5));
  CHECK(c.velocity.y == Approx(0.25));
}

TEST_CASE("a line that leaves the disk only where the speed allows", "[velocity_program]") {
  // x >= 0.6 within speed 1, nearest to (0, -2): on the circle at x = 0.6, y = -0.8.
  const VelocityChoice c = closest_permitted_velocity({at_least_x(0.6)}, 1.0, {0.0, -2.0});
  CHECK(c.feasible);
  CHECK(c.velocity.x == Approx(0.6));
  CHECK(c.velocity.y == Approx(-0.8));
}

TEST_CASE("infeasible: the velocity that least violates the worst constraint",
          "[velocity_program]") {
  // x >= 1 and x <= -1: x = 0 violates each by 1, anything else one of them by more.
  const VelocityChoice c =
      closest_permitted_velocity({at_least_x(1.0), at_most_x(-1.0)}, 5.0, {0.0, 0.0});
  CHECK_FALSE(c.feasible);
  CHECK(c.velocity.x == Approx(0.0).margin(1e-12));
  // Beyond the top speed: x >= 2 with speed 1 is met as nearly as the disk allows.
  const VelocityChoice far = closest_permitted_velocity({at_least_x(2.0)}, 1.0, {0.0, 0.0});
  CHECK_FALSE(far.feasible);
  CHECK(far.velocity.x == Approx(1.0));
  CHECK(far.velocity.y == Approx(0.0).margin(1e-12));
}

TEST_CASE("random programs: feasible answers satisfy every plane and beat nearby points",
          "[velocity_program]") {
  std::uint64_t s = 12345;
  auto uniform = [&] {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) / 9007199254740992.0;
  };
  int feasible = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<VelocityConstraint> planes;
    const int n = 1 + static_cast<int>(uniform() * 5);
    for (int k = 0; k < n; ++k) {
      const double a = 2 * M_PI * uniform();
      planes.push_back({{uniform() - 0.5, uniform() - 0.5}, {std::cos(a), std::sin(a)}});
    }
    const Vec2 preferred{4 * uniform() - 2, 4 * uniform() - 2};
    const VelocityChoice c = closest_permitted_velocity(planes, 1.0, preferred);
    if (!c.feasible) continue;
    ++feasible;
    const auto permitted = [&](Vec2 v) {
      if (norm(v) > 1.0 + 1e-9) return false;
      for (const VelocityConstraint& h : planes)
        if (cross(h.direction, v - h.point) < -1e-9) return false;
      return true;
    };
    REQUIRE(permitted(c.velocity));
    // No permitted point of a fine grid is nearer to the preferred velocity.
    for (double x = -1; x <= 1; x += 0.05)
      for (double y = -1; y <= 1; y += 0.05)
        if (permitted({x, y}))
          CHECK(distance({x, y}, preferred) >= distance(c.velocity, preferred) - 1e-9);
  }
  CHECK(feasible > 100);
}
