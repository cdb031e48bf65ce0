#include <catch2/catch.hpp>

#include <cmath>

#include "core/random_stream.hpp"
#include "geometry/uniform_density.hpp"
#include "scenarios/scenario.hpp"
#include "sim/coverage_run.hpp"
#include "sim/metrics_sampler.hpp"
#include "sim/network_metrics.hpp"
#include "tests/robot/paper_scenarios.hpp"

using namespace covsim;
using covsim::test::paper;

namespace {

Scenario with_network(const std::string& name, const nlohmann::json& network) {
  nlohmann::json j = paper(name).json;
  j["network"] = network;
  return parse_scenario(j, name + " (with network)", std::string(COVSIM_SOURCE_DIR) + "/scenarios");
}
}  // namespace

TEST_CASE("the default network, stated or not, reproduces the centralized run bit for bit",
          "[network]") {
  const nlohmann::json stated = {{"range", nullptr},
                                 {"line_of_sight", false},
                                 {"broadcast_period", 0.1},
                                 {"loss", {{"model", "none"}}},
                                 {"delay", {{"model", "constant"}, {"value", 0.0}}}};
  for (const char* name : {"u_shape.json", "two_obstacles.json"}) {
    const CoverageOutcome central = run_coverage(paper(name));
    const CoverageOutcome explicit_default = run_coverage(with_network(name, stated));
    CHECK_FALSE(explicit_default.decentralized);
    CHECK(explicit_default.fingerprint == central.fingerprint);
    CHECK(explicit_default.events == central.events);
    for (std::size_t i = 0; i < central.robots.size(); ++i) {
      CHECK(explicit_default.robots[i].position == central.robots[i].position);
      CHECK(explicit_default.robots[i].virtual_generator == central.robots[i].virtual_generator);
    }
  }
}

TEST_CASE("at 30% Bernoulli loss the paper's scenarios still converge", "[network]") {
  const nlohmann::json lossy = {
      {"loss", {{"model", "bernoulli"}, {"p", 0.3}}},
      {"delay", {{"model", "exponential"}, {"base", 0.01}, {"mean", 0.03}}},
      {"random_phase", true}};
  for (const char* name : {"u_shape.json", "two_obstacles.json", "l_shape.json", "fig2c.json"}) {
    INFO(name);
    const Scenario s = with_network(name, lossy);
    const CoverageOutcome out = run_coverage(s);
    CHECK(out.decentralized);
    CHECK(out.converged);
    if (s.robot_positions.size() > 1) {
      CHECK(out.network.sent > 0);
      const double observed =
          static_cast<double>(out.network.lost) / static_cast<double>(out.network.sent);
      const double n = static_cast<double>(out.network.sent);
      CHECK(std::abs(observed - 0.3) <= 5 * std::sqrt(0.21 / n));
      CHECK(out.network.delivered + out.network.lost + out.network.unreachable == out.network.sent);
    }
    for (const auto& r : out.robots)
      CHECK(s.environment->contains(r.position));
  }
}

TEST_CASE("at 100% loss every robot covers Ω alone, and the run ends", "[network]") {
  const Scenario s =
      with_network("two_obstacles.json", {{"loss", {{"model", "bernoulli"}, {"p", 1.0}}}});
  const CoverageOutcome out = run_coverage(s);
  CHECK(out.network.delivered == 0);
  // Alone, each robot's cell is Ω: all head for Ω's centroid (or its projection).
  const UniformDensity d;
  const CellIntegrator integrator(*s.environment, d);
  const VoronoiPartition whole(integrator, {Vec2{0.5, 0.5}});
  const Vec2 c = whole.summary(0).centroid;
  for (const auto& r : out.robots)
    CHECK(distance(r.virtual_target, c) < 1e-9);
  CHECK(out.converged);
}

TEST_CASE("a short range and walls split the communication graph", "[network]") {
  const Scenario s =
      with_network("office.json", {{"range", 3.0}, {"line_of_sight", true}, {"staleness", 1.0}});
  Scenario shorter = s;
  // Periodic Lloyd updates spread the robots from the corridor into the rooms.
  shorter.coverage.mode = LoopMode::periodic;
  shorter.coverage.loop1_period = SimTime::from_seconds(1.0);
  shorter.coverage.max_time = SimTime::from_seconds(200.0);
  struct Graphs final : CoverageObserver {
    std::size_t max_components = 0;
    double max_age = 0.0;
    std::unique_ptr<NetworkMetrics> metrics;
    void on_sample(SimTime, const CoverageController& c) override {
      if (!metrics) metrics = std::make_unique<NetworkMetrics>(c.environment());
      const NetworkSample n = metrics->sample(c);
      max_components = std::max(max_components, n.graph.components);
      max_age = std::max(max_age, n.info_age_max);
    }
  } graphs;
  const CoverageOutcome out = run_coverage(shorter, &graphs);
  CHECK(out.network.unreachable > 0);
  // Robots far from a sender are counted out of range without a test each, so check that
  // every transmission still has exactly one fate.
  CHECK(out.network.sent == out.network.delivered + out.network.lost + out.network.unreachable);
  CHECK(graphs.max_components > 1);  // robots spread into rooms lose sight of each other
  CHECK(graphs.max_age <= 1.0);      // nothing past the staleness limit counts
  CHECK(out.sim_time <= SimTime::from_seconds(200.0));
}

TEST_CASE("sampled, noisy and lossy range sensing still covers the U", "[sensing]") {
  nlohmann::json j = paper("u_shape.json").json;
  j["sensor"] = {{"range", 0.1}, {"period", 0.3}, {"noise", {{"sigma", 0.002}}}, {"dropout", 0.3}};
  const Scenario s = parse_scenario(j, "u_shape with a poor sensor",
                                    std::string(COVSIM_SOURCE_DIR) + "/scenarios");
  CHECK(s.coverage.sensor.period == SimTime::from_seconds(0.3));
  struct Inside final : CoverageObserver {
    const Environment* env;
    std::size_t outside = 0;
    void on_motion(SimTime, const Robot& r) override {
      outside += env->contains(r.position) ? 0 : 1;
    }
  } inside;
  inside.env = s.environment.get();
  const CoverageOutcome a = run_coverage(s, &inside);
  CHECK(a.converged);
  CHECK(inside.outside == 0);
  const CoverageOutcome b = run_coverage(s);
  CHECK(a.fingerprint == b.fingerprint);  // noise and dropout come from seeded streams
  // Without the imperfections the run differs.
  CHECK(a.fingerprint != run_coverage(paper("u_shape.json")).fingerprint);
}

TEST_CASE("metrics.algebraic_connectivity_robots bounds the runs whose samples get λ2",
          "[network][metrics]") {
  // u_shape's 5 robots, all in range of each other: a connected graph at every sample.
  nlohmann::json j = with_network("u_shape.json", {{"range", 5.0}}).json;
  const auto sampled = [&](std::uint64_t limit) {
    j["metrics"] = {{"algebraic_connectivity_robots", limit}};
    const Scenario s = parse_scenario(j, "u_shape", std::string(COVSIM_SOURCE_DIR) + "/scenarios");
    CHECK(s.coverage.algebraic_connectivity_robots == limit);
    MetricsSampler sampler;
    const CoverageOutcome out = run_coverage(s, &sampler);
    return std::make_pair(out.fingerprint, sampler.samples());
  };
  const auto [with_print, with] = sampled(5);
  const auto [without_print, without] = sampled(4);
  CHECK(with_print == without_print);  // a measure of the run, not part of it
  REQUIRE(with.size() == without.size());
  REQUIRE_FALSE(with.empty());
  for (std::size_t k = 0; k < with.size(); ++k) {
    CHECK(with[k].network.graph.components == 1);
    CHECK(with[k].network.graph.algebraic_connectivity == Approx(5.0));  // complete: n
    CHECK(std::isnan(without[k].network.graph.algebraic_connectivity));
    CHECK(without[k].network.graph.diameter == with[k].network.graph.diameter);
  }
  CHECK(summarize_communication(with).algebraic_connectivity_min == Approx(5.0));
  CHECK(std::isnan(summarize_communication(without).algebraic_connectivity_min));
}

TEST_CASE("messages without delay are read in one event per receiver and instant", "[network]") {
  // office's 30 robots hear each other: 870 messages an instant, read by 30 events (one per
  // receiver) beside the 30 broadcasts and the robots' own events.
  Scenario s = with_network("office.json", {{"loss", {{"model", "bernoulli"}, {"p", 0.1}}}});
  s.coverage.max_time = SimTime::from_seconds(20.0);
  const CoverageOutcome out = run_coverage(s);
  REQUIRE(out.decentralized);
  CHECK(out.network.delivered > 50'000);
  CHECK(out.events * 4 < out.network.delivered);
}

TEST_CASE("a robot's own cell is kept for the generators it came from, bit for bit",
          "[network][cells]") {
  const Scenario s = paper("u_shape.json");
  const UniformDensity d;
  const CellIntegrator integrator(*s.environment, d);
  RandomStream rng(3, 0, "own-cell-cache-test");
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec2> g(2 + rng.below(30));
    for (Vec2& p : g)
      p = {rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0)};
    if (trial == 0) g[1].x = 0.0;
    const std::size_t self = rng.below(g.size());
    OwnCellCache cache;
    const auto same = [](const CellSummary& a, const CellSummary& b) {
      return a.mass == b.mass && a.centroid == b.centroid && a.cost == b.cost;
    };
    ConvexPolygon plain_cell, cached_cell, kept_cell;
    const CellSummary plain = own_cell_summary(
        integrator,
        Knowledge{g, self, Generators::virtual_generators, nullptr, std::nullopt, nullptr},
        &plain_cell);
    const Knowledge k{g, self, Generators::virtual_generators, nullptr, std::nullopt, &cache};
    CellSummary found;
    CHECK(cache.find(integrator, g, self, found) == nullptr);
    CHECK(same(own_cell_summary(integrator, k, &cached_cell), plain));  // computed, stored
    REQUIRE(cache.find(integrator, g, self, found) != nullptr);
    CHECK(same(found, plain));
    CHECK(same(own_cell_summary(integrator, k, &kept_cell), plain));  // from the cache
    CHECK(cached_cell == plain_cell);
    CHECK(kept_cell == plain_cell);
    // Any other generators, self or integrator miss: one ulp, a zero's sign, another robot.
    std::vector<Vec2> moved = g;
    moved[0].y = std::nextafter(moved[0].y, 2.0);
    CHECK(cache.find(integrator, moved, self, found) == nullptr);
    CHECK(cache.find(integrator, g, (self + 1) % g.size(), found) == nullptr);
    const CellIntegrator other(*s.environment, d);  // equal, but another: no assumption
    CHECK(cache.find(other, g, self, found) == nullptr);
    if (trial == 0) {
      std::vector<Vec2> signed_zero = g;
      signed_zero[1].x = -0.0;
      CHECK(cache.find(integrator, signed_zero, self, found) == nullptr);
    }
    const Knowledge km{moved, self, Generators::virtual_generators, nullptr, std::nullopt, &cache};
    CHECK(same(own_cell_summary(integrator, km),
               own_cell_summary(integrator, Knowledge{moved, self, Generators::virtual_generators,
                                                      nullptr, std::nullopt, nullptr})));
  }
}
