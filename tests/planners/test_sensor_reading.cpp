#include <catch2/catch.hpp>

#include <cmath>

#include "core/random_stream.hpp"
#include "planners/local_tangent_graph.hpp"
#include "planners/sensor_reading.hpp"

using namespace covsim;

TEST_CASE("range noise moves sensed points along their rays with the given sigma", "[sensor]") {
  const Environment env({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {});
  const Vec2 p{1, 1};
  const SensorReading clean = sense(env, p, INFINITY);
  REQUIRE(clean.visible().pieces.size() == 4);
  RandomStream rng(5, 0, "noise-test");
  double sum = 0, sum2 = 0;
  int n = 0;
  for (int k = 0; k < 5000; ++k) {
    SensorReading noisy = clean;
    add_range_noise(noisy, rng, 0.01, env.tolerance());
    for (std::size_t i = 0; i < clean.visible().pieces.size(); ++i) {
      for (auto [c, q] : {std::pair{clean.visible().pieces[i].a, noisy.visible().pieces[i].a},
                          std::pair{clean.visible().pieces[i].b, noisy.visible().pieces[i].b}}) {
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
  CHECK(unchanged.visible().pieces[0].a == clean.visible().pieces[0].a);
  // Contacts are never noisy.
  const SensorReading touching = sense(env, {0, 2}, 0.0);
  SensorReading t = touching;
  add_range_noise(t, rng, 0.5, env.tolerance());
  CHECK(t.contacts.size() == 1);
  CHECK(t.contacts[0].a == touching.contacts[0].a);
}

TEST_CASE("range noise keeps the visible boundary's continuity: a shared point moves once",
          "[sensor]") {
  // A room with a box: from (1, 1) the room's walls are seen in stretches, cut where the
  // box hides them.
  const Environment env({{0, 0}, {6, 0}, {6, 6}, {0, 6}}, {{{3, 3}, {4, 3}, {4, 4}, {3, 4}}});
  const SensorReading clean = sense(env, {1, 1}, INFINITY);
  RandomStream rng(7, 0, "noise-test");
  SensorReading noisy = clean;
  add_range_noise(noisy, rng, 0.05, env.tolerance());
  const auto& c = clean.visible().pieces;
  const auto& n = noisy.visible().pieces;
  REQUIRE(c.size() == n.size());
  std::size_t joins = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::size_t next = (k + 1) % c.size();
    if (!within(c[k].b, c[next].a, env.tolerance())) continue;
    ++joins;
    CHECK(n[k].b == n[next].a);
  }
  CHECK(joins >= 4);
  // The discontinuities are the noisy pieces' ends, as many as before.
  REQUIRE(noisy.visible().discontinuities.size() == clean.visible().discontinuities.size());
  for (Vec2 o : noisy.visible().discontinuities) {
    bool end = false;
    for (const SensedPiece& p : n)
      end = end || o == p.a || o == p.b;
    CHECK(end);
  }
}

TEST_CASE("a contact sensor feels the walls it touches and sees nothing", "[sensor]") {
  const Environment env({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {});
  const SensorReading corner = sense(env, {0, 0}, 0.0);
  CHECK(corner.visible().pieces.empty());
  CHECK(corner.contacts.size() == 2);
  CHECK(sense(env, {2, 2}, 0.0).contacts.empty());
}

TEST_CASE("an open way to the goal makes the goal the best tangent node", "[sensor]") {
  // What TangentBug's shortcut rests on: when open_toward holds, the full choice over the
  // visible boundary's nodes picks the goal, by a margin; the reading built from the pieces
  // agrees with the one answered from Ω whenever it says open.
  std::vector<std::vector<Vec2>> holes;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      const Vec2 c{2.0 + 3.0 * i, 2.0 + 3.0 * j};
      holes.push_back(
          {c + Vec2{-0.6, -0.4}, c + Vec2{0.5, -0.7}, c + Vec2{0.8, 0.5}, c + Vec2{-0.3, 0.6}});
    }
  }
  const Environment env({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, holes);
  const double margin = 1e3 * env.tolerance(), tolerance = env.tolerance();
  RandomStream rng(11, 0, "open");
  std::size_t open = 0, closed = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec2 x{rng.uniform(0, 10), rng.uniform(0, 10)};
    if (!env.contains(x)) continue;
    const Vec2 goal{rng.uniform(0, 10), rng.uniform(0, 10)};
    for (double range : {0.5, 2.0, double(INFINITY)}) {
      const SensorReading r = sense(env, x, range);
      SensorReading eager = r;
      eager.set_visible(r.visible());
      if (!r.open_toward(goal, margin)) {
        ++closed;
        continue;
      }
      ++open;
      CHECK(eager.open_toward(goal, margin));
      const std::vector<TangentNode> nodes = tangent_nodes(r, goal, INFINITY, tolerance);
      REQUIRE_FALSE(nodes.empty());
      CHECK(nodes.front().is_goal);
      for (std::size_t i = 1; i < nodes.size(); ++i)
        CHECK(nodes[i].heuristic > nodes.front().heuristic);
    }
  }
  CHECK(open > 1000);
  CHECK(closed > 1000);
}
