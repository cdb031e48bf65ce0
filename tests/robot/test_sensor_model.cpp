// The sensor model alone (robot/sensor_model): what a robot's planner is given at a loop-2
// step, for each range, with noise and dropout drawn from the robot's own streams, and with
// readings that go stale between periodic "sense" events.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "core/kernel.hpp"
#include "robot/sensor_model.hpp"

using namespace covsim;

namespace {
// A 2 m × 2 m room with a 0.5 m box in its middle.
Environment room_with_box() {
  return Environment({{0, 0}, {2, 0}, {2, 2}, {0, 2}},
                     {{{0.75, 0.75}, {0.75, 1.25}, {1.25, 1.25}, {1.25, 0.75}}});
}

SensorConfig sensor_with_range(double range) {
  SensorConfig c;
  c.range = range;
  return c;
}

double visible_length(const SensorReading& r) {
  double l = 0.0;
  for (const SensedPiece& p : r.visible().pieces)
    l += distance(p.a, p.b);
  return l;
}

// Every robot at its own fixed point, read through the model's position callback.
struct Positions {
  std::vector<Vec2> at;
  std::function<Vec2(std::uint32_t)> callback() {
    return [this](std::uint32_t i) { return at[i]; };
  }
};
}  // namespace

TEST_CASE("an exact sensor reads the room afresh at each step, as its range allows",
          "[sensor_model]") {
  const Environment env = room_with_box();
  Kernel kernel(7);
  Positions pos{{{0.25, 0.25}}};
  const Vec2 p{0.25, 0.25};

  SECTION("range 0: contact only") {
    SensorModel model(kernel, env, sensor_with_range(0.0), 1, pos.callback());
    const SensorReading r = model.reading(0, p);
    CHECK(r.position == p);
    CHECK(r.origin == p);
    CHECK(r.range == 0.0);
    CHECK(r.visible().pieces.empty());
    CHECK(r.contacts.empty());  // away from every wall
    // On the bottom wall it feels that wall, and still sees nothing.
    const SensorReading on_wall = model.reading(0, {1.0, 0.0});
    CHECK(on_wall.visible().pieces.empty());
    REQUIRE(on_wall.contacts.size() == 1);
    CHECK(on_wall.contacts[0].a.y == 0.0);
    CHECK(on_wall.contacts[0].b.y == 0.0);
  }

  SECTION("a finite range: only walls within it") {
    SensorModel model(kernel, env, sensor_with_range(0.5), 1, pos.callback());
    const SensorReading r = model.reading(0, p);
    CHECK(r.range == 0.5);
    REQUIRE_FALSE(r.visible().pieces.empty());
    for (const SensedPiece& piece : r.visible().pieces) {
      CHECK(distance(piece.a, p) <= 0.5 + 1e-9);
      CHECK(distance(piece.b, p) <= 0.5 + 1e-9);
    }
    // The two walls 0.25 m away, each seen from the corner to 0.25 + √(0.5² - 0.25²); the
    // box is 0.71 m away.
    const double seen = 0.25 + std::sqrt(0.1875);
    CHECK(visible_length(r) == Approx(2 * seen).epsilon(1e-9));
  }

  SECTION("an infinite range: every wall in sight, the box's far side hidden") {
    SensorModel model(kernel, env, SensorConfig{}, 1, pos.callback());
    const SensorReading r = model.reading(0, p);
    CHECK(std::isinf(r.range));
    // The outer walls (8 m) less what the box hides behind it, and the box's two near sides:
    // the rays past its corners (1.25, 0.75) and (0.75, 1.25) meet the far walls at 1.125.
    CHECK(visible_length(r) == Approx(8.0 - 2 * 0.875 + 1.0).epsilon(1e-12));
    const SensorReading exact = sense(env, p, INFINITY);
    REQUIRE(exact.visible().pieces.size() == r.visible().pieces.size());
    for (std::size_t k = 0; k < r.visible().pieces.size(); ++k) {
      CHECK(r.visible().pieces[k].a == exact.visible().pieces[k].a);
      CHECK(r.visible().pieces[k].b == exact.visible().pieces[k].b);
    }
    // In an empty room every wall is seen whole.
    const Environment square({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {});
    SensorModel open(kernel, square, SensorConfig{}, 1, pos.callback());
    CHECK(visible_length(open.reading(0, {0.3, 1.7})) == Approx(8.0).epsilon(1e-12));
  }
}

TEST_CASE("range noise comes from each robot's sensor-noise stream, N(0, σ²) along the rays",
          "[sensor_model]") {
  const Environment square({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {});
  const double sigma = 0.02;
  Kernel kernel(11);
  Positions pos{{{1.0, 1.0}, {1.0, 1.0}}};
  SensorConfig config;
  config.noise_sigma = sigma;
  SensorModel model(kernel, square, config, 2, pos.callback());
  // The same draws as the stream named for robot i, applied to an exact reading.
  RandomStream robot0 = kernel.stream(0, "sensor-noise");
  const Vec2 p{1.0, 1.0};
  double sum = 0.0, sum2 = 0.0;
  std::size_t n = 0;
  bool robots_differ = false;
  for (int k = 0; k < 2000; ++k) {
    const SensorReading r = model.reading(0, p);
    const SensorReading exact = sense(square, p, INFINITY);
    SensorReading expected = exact;
    add_range_noise(expected, robot0, sigma, square.tolerance());
    REQUIRE(r.visible().pieces.size() == expected.visible().pieces.size());
    for (std::size_t j = 0; j < r.visible().pieces.size(); ++j) {
      REQUIRE(r.visible().pieces[j].a == expected.visible().pieces[j].a);
      REQUIRE(r.visible().pieces[j].b == expected.visible().pieces[j].b);
      // Each piece's end is measured once (shared with the next piece).
      const double e =
          distance(r.visible().pieces[j].b, p) - distance(exact.visible().pieces[j].b, p);
      sum += e;
      sum2 += e * e;
      ++n;
    }
    const SensorReading other = model.reading(1, p);
    robots_differ = robots_differ || !(other.visible().pieces[0].b == r.visible().pieces[0].b);
    CHECK(r.origin == p);  // without a period a reading is always taken where the robot is
  }
  const double mean = sum / double(n);
  const double sd = std::sqrt(sum2 / double(n) - mean * mean);
  INFO("mean " << mean << ", sd " << sd << " over " << n);
  CHECK(std::abs(mean) < 4.0 * sigma / std::sqrt(double(n)));
  CHECK(sd == Approx(sigma).epsilon(0.05));
  CHECK(robots_differ);  // each robot its own stream
}

TEST_CASE("a lost reading leaves the last one, never the first, at the dropout rate",
          "[sensor_model]") {
  const Environment square({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {});
  const double p_loss = 0.3;
  Kernel kernel(5);
  Positions pos{{{0.5, 0.5}}};
  SensorConfig config;
  config.dropout = p_loss;
  SensorModel model(kernel, square, config, 1, pos.callback());
  RandomStream draws = kernel.stream(0, "sensor-dropout");
  Vec2 origin{-1, -1};
  std::size_t lost = 0;
  const int n = 5000;
  for (int k = 0; k < n; ++k) {
    // A robot walking along the bottom wall: every step a new place.
    const Vec2 p{0.1 + 1.8 * k / n, 0.0};
    const SensorReading r = model.reading(0, p);
    CHECK(r.position == p);
    CHECK(r.contacts.size() == 1);  // contacts are current even when the range part is old
    if (k == 0) {
      CHECK(r.origin == p);  // the first reading is never lost
    } else {
      const bool drawn_lost = draws.bernoulli(p_loss);
      REQUIRE((r.origin == origin) == drawn_lost);
      lost += drawn_lost ? 1 : 0;
    }
    origin = r.origin;
  }
  const double rate = double(lost) / (n - 1);
  INFO("lost " << rate);
  CHECK(std::abs(rate - p_loss) < 4.0 * std::sqrt(p_loss * (1 - p_loss) / (n - 1)));
}

TEST_CASE("with a period, a reading is as old as the last sense event", "[sensor_model]") {
  const Environment square({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {});
  Kernel kernel(3);
  Positions pos{{{0.5, 0.5}, {1.5, 1.5}}};
  SensorConfig config;
  config.range = 0.75;
  config.period = SimTime::from_seconds(0.5);
  SensorModel model(kernel, square, config, 2, pos.callback());
  model.start(SimTime::zero());
  kernel.run_until(SimTime::zero());  // the first readings, where the robots start
  pos.at = {{0.6, 0.5}, {1.5, 1.4}};
  kernel.run_until(SimTime::from_seconds(0.3));
  SensorReading r = model.reading(0, pos.at[0]);
  CHECK(r.origin == Vec2{0.5, 0.5});  // stale: taken at t = 0
  CHECK(r.position == Vec2{0.6, 0.5});
  CHECK(r.range == 0.75);
  // Asked again before the next event: the same range part, however often asked.
  CHECK(model.reading(0, {0.7, 0.5}).origin == Vec2{0.5, 0.5});
  // Contacts are the robot's own now, though the range part was taken away from the wall.
  CHECK(model.reading(0, {0.6, 0.0}).contacts.size() == 1);
  kernel.run_until(SimTime::from_seconds(0.5));
  CHECK(model.reading(0, pos.at[0]).origin == Vec2{0.6, 0.5});
  CHECK(model.reading(1, pos.at[1]).origin == Vec2{1.5, 1.4});
  // What was sensed at the origin: walls within 0.75 m of (0.6, 0.5), not of the robot.
  pos.at[0] = {1.9, 1.9};
  kernel.run_until(SimTime::from_seconds(0.9));
  r = model.reading(0, pos.at[0]);
  REQUIRE_FALSE(r.visible().pieces.empty());
  for (const SensedPiece& piece : r.visible().pieces)
    CHECK(distance(piece.a, {0.6, 0.5}) <= 0.75 + 1e-9);
  CHECK(kernel.events_dispatched() == 2 * 2);  // t = 0 and 0.5, two robots
}
