#include <catch2/catch.hpp>

#include <cmath>

#include "planners/sensor_reading.hpp"

using namespace covsim;

TEST_CASE("range noise moves sensed points along their rays with the given sigma", "[sensor]") {
  const Environment env({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {});
  const Vec2 p{1, 1};
  const SensorReading clean = sense(env, p, INFINITY);
  REQUIRE(clean.visible.pieces.size() == 4);
  RandomStream rng(5, 0, "noise-test");
  double sum = 0, sum2 = 0;
  int n = 0;
  for (int k = 0; k < 5000; ++k) {
    SensorReading noisy = clean;
    add_range_noise(noisy, rng, 0.01, env.tolerance());
    for (std::size_t i = 0; i < clean.visible.pieces.size(); ++i) {
      for (auto [c, q] : {std::pair{clean.visible.pieces[i].a, noisy.visible.pieces[i].a},
                          std::pair{clean.visible.pieces[i].b, noisy.visible.pieces[i].b}}) {
        // Along the ray from the robot.
        CHECK(std::abs(cross(c - p, q - p)) < 1e-9);
        const double e = norm(q - p) - norm(c - p);
        sum += e;
        sum2 += e * e;
        ++n;
      }
    }
  }
  CHECK(std::abs(sum / n) < 5 * 0.01 / std::sqrt(n));
  CHECK(std::sqrt(sum2 / n) == Approx(0.01).epsilon(0.02));
  SensorReading unchanged = clean;
  add_range_noise(unchanged, rng, 0.0, env.tolerance());
  CHECK(unchanged.visible.pieces[0].a == clean.visible.pieces[0].a);
  // Contacts are never noisy.
  const SensorReading touching = sense(env, {0, 2}, 0.0);
  SensorReading t = touching;
  add_range_noise(t, rng, 0.5, env.tolerance());
  CHECK(t.contacts.size() == 1);
  CHECK(t.contacts[0].a == touching.contacts[0].a);
}
