// ORCA on its own: agents that move at once with the velocities it chooses keep their bodies
// apart, reach their goals, and pass each other on the right; without the bias two robots
// meeting exactly head on stop face to face.
#include <catch2/catch.hpp>

#include <cmath>

#include "robot/collision_avoidance_registry.hpp"
#include "robot/orca_avoidance.hpp"

using namespace covsim;

namespace {

struct Agent {
  Vec2 position, goal, velocity;
};

struct Outcome {
  double least = INFINITY;  // least distance between two centres
  bool all_reached = false;
};

// Every agent chooses at once from the others' last velocities, as robots updated together.
Outcome simulate(std::vector<Agent> agents, double radius, double bias, double seconds,
                 const std::vector<bool>& standing = {}) {
  const double speed = 0.1, dt = 0.1;
  OrcaAvoidance orca(2.0, 0.0, bias);
  Outcome out;
  for (int step = 0; step < static_cast<int>(seconds / dt); ++step) {
    std::vector<Vec2> next(agents.size());
    for (std::size_t i = 0; i < agents.size(); ++i) {
      const Agent& a = agents[i];
      if (!standing.empty() && standing[i]) {
        next[i] = {};
        continue;
      }
      std::vector<SensedNeighbor> near;
      for (std::size_t j = 0; j < agents.size(); ++j)
        if (j != i && distance(agents[j].position, a.position) < orca.range(radius, speed, dt))
          near.push_back({agents[j].position, agents[j].velocity});
      Vec2 preferred = (a.goal - a.position) / dt;
      if (norm(preferred) > speed) preferred = (speed / norm(preferred)) * preferred;
      next[i] = orca.velocity({a.position, a.velocity, preferred, radius, speed, dt, near});
      REQUIRE(norm(next[i]) <= speed * (1 + 1e-9));
    }
    for (std::size_t i = 0; i < agents.size(); ++i) {
      agents[i].velocity = next[i];
      agents[i].position += dt * next[i];
    }
    for (std::size_t i = 0; i < agents.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        out.least = std::min(out.least, distance(agents[i].position, agents[j].position));
  }
  out.all_reached = true;
  for (std::size_t i = 0; i < agents.size(); ++i)
    if (standing.empty() || !standing[i])
      out.all_reached = out.all_reached && distance(agents[i].position, agents[i].goal) < 1e-3;
  return out;
}

}  // namespace

TEST_CASE("two robots meeting head on pass each other on their right", "[orca]") {
  const Outcome o = simulate({{{0, 0}, {2, 0}, {}}, {{2, 0}, {0, 0}, {}}}, 0.1, 0.1, 60);
  CHECK(o.all_reached);
  CHECK(o.least >= 0.2 - 1e-9);
}

TEST_CASE("without the bias, robots meeting exactly head on stop face to face", "[orca]") {
  const Outcome o = simulate({{{0, 0}, {2, 0}, {}}, {{2, 0}, {0, 0}, {}}}, 0.1, 0.0, 60);
  CHECK_FALSE(o.all_reached);
  CHECK(o.least >= 0.2 - 1e-9);
}

TEST_CASE("eight robots crossing a circle to the opposite side never touch", "[orca]") {
  std::vector<Agent> agents;
  for (int k = 0; k < 8; ++k) {
    const double a = 2 * M_PI * k / 8;
    const Vec2 p{std::cos(a), std::sin(a)};
    agents.push_back({p, -p, {}});
  }
  const Outcome o = simulate(agents, 0.1, 0.1, 200);
  CHECK(o.all_reached);
  CHECK(o.least >= 0.2 - 1e-9);
}

TEST_CASE("a robot passing a standing one avoids it alone", "[orca]") {
  // The standing robot sits on the straight way; it never moves.
  const Outcome o =
      simulate({{{0, 0}, {2, 0}, {}}, {{1, 0.01}, {1, 0.01}, {}}}, 0.1, 0.1, 80, {false, true});
  CHECK(o.all_reached);
  CHECK(o.least >= 0.2 - 1e-9);
}

TEST_CASE("ORCA leaves a preferred velocity that needs no avoiding untouched", "[orca]") {
  OrcaAvoidance orca(2.0, 0.0, 0.1);
  const std::vector<SensedNeighbor> near{{{1.0, 1.0}, {0.0, 0.0}}};
  const Vec2 preferred{0.0123, -0.0456};
  CHECK(orca.velocity({{0, 0}, {}, preferred, 0.1, 0.1, 0.1, near}) == preferred);
  // Its range: two bodies closing at twice the top speed for the horizon, unless set.
  CHECK(orca.range(0.1, 0.1, 0.1) == Approx(0.2 + 0.4));
  CHECK(OrcaAvoidance(2.0, 1.5, 0.1).range(0.1, 0.1, 0.1) == 1.5);
}

TEST_CASE("the avoidance registry holds none and orca with their defaults", "[orca]") {
  CHECK(collision_avoidance_registry().names() == std::vector<std::string>{"none", "orca"});
  AvoidanceConfig c;
  c.type = "orca";
  const auto orca = make_collision_avoidance(c);
  CHECK(orca->range(0.05, 0.1, 0.1) == Approx(0.1 + 0.4));
  CHECK_THROWS_WITH(make_collision_avoidance(AvoidanceConfig{"rvo9", {}}),
                    Catch::Matchers::Contains("none, orca"));
}
