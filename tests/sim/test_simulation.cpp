#include <catch2/catch.hpp>

#include "net/bernoulli_loss.hpp"
#include "scenarios/scenario.hpp"
#include "sim/simulation.hpp"
#include "tests/robot/paper_scenarios.hpp"

using namespace covsim;
using covsim::test::paper;

TEST_CASE("a run stepped event by event, or in chunks, equals the whole run", "[simulation]") {
  Scenario lossy = paper("two_obstacles.json");
  lossy.coverage.network.channel.loss = std::make_shared<const BernoulliLoss>(0.2);
  for (const Scenario& s : {paper("u_shape.json"), lossy}) {
    const CoverageOutcome whole = run_coverage(s);
    Simulation stepped(s);
    std::uint64_t steps = 0;
    while (stepped.step())
      ++steps;
    CHECK(stepped.finished());
    CHECK(stepped.fingerprint() == whole.fingerprint);
    CHECK(stepped.events() == whole.events);
    CHECK(steps + 1 == whole.events);  // the last step ends the run
    CHECK(stepped.outcome().stop_reason == whole.stop_reason);
    CHECK(stepped.outcome().cost_real == whole.cost_real);
    Simulation chunked(s);
    for (double t = 0.7; !chunked.finished(); t += 0.7)
      chunked.run_until(SimTime::from_seconds(t));
    CHECK(chunked.fingerprint() == whole.fingerprint);
    CHECK(chunked.outcome().time_to_1_percent == whole.time_to_1_percent);
  }
}

TEST_CASE("a different seed given to the simulation replaces the scenario's", "[simulation]") {
  Scenario s = paper("u_shape.json");
  s.coverage.network.channel.loss = std::make_shared<const BernoulliLoss>(0.3);
  Simulation a(s, 5), b(s, 6);
  a.run();
  b.run();
  CHECK(a.fingerprint() != b.fingerprint());
  Scenario five = s;
  five.seed = 5;
  CHECK(run_coverage(five).fingerprint == a.fingerprint());
}

TEST_CASE("the external law drives robots to targets set from outside", "[simulation]") {
  Scenario s = paper("two_obstacles.json");
  s.coverage.law.type = "external";
  s.coverage.max_time = SimTime::from_seconds(30.0);
  Simulation sim(s);
  sim.set_target(0, {0.9, 0.9});
  sim.run_until(SimTime::from_seconds(20.0));
  CHECK_FALSE(sim.finished());
  CHECK(distance(sim.controller().robots()[0].position, Vec2{0.9, 0.9}) < 1e-9);
  // The others held their positions.
  CHECK(sim.controller().robots()[1].position == s.robot_positions[1]);
  sim.run();
  CHECK(sim.outcome().stop_reason == "max_time");
  Simulation paper_law(paper("u_shape.json"));
  CHECK_THROWS_AS(paper_law.set_target(0, {0.5, 0.5}), std::logic_error);
}
