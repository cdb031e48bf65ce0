// Whole runs of robots that do not know Ω (environment.known): they map it as they cover,
// their maps never mark free space inside an obstacle, a map from every reading holds what is
// visible from where the readings were taken, maps are shared over the network, and the runs
// converge near the cost of the run with Ω known.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "robot/coverage_controller.hpp"
#include "robot/mapping.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/metrics_sampler.hpp"
#include "sim/simulation.hpp"
#include "tests/robot/paper_scenarios.hpp"

using namespace covsim;
using Catch::Matchers::Contains;
using covsim::test::paper;

namespace {

Scenario unknown(const std::string& name, const char* known, nlohmann::json range,
                 const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json j = paper(name).json;
  j["environment"]["known"] = known;
  j["sensor"]["range"] = std::move(range);
  for (const auto& [key, value] : extra.items())
    j[key] = value;
  return covsim::test::parse_beside_paper(j, name);
}

// Every cell a map marks has its centre in Ω.
void check_inside(const Mapping& m, std::size_t robots) {
  const std::uint64_t merged = m.merged().count();
  CHECK(merged > 0);
  CHECK(m.merged().common(m.free_cells()) == merged);
  for (std::uint32_t i = 0; i < robots; ++i) {
    const KnownLattice& l = m.lattice(i);
    CHECK(l.common(m.free_cells()) == l.count());
    CHECK(l.common(m.merged()) == l.count());  // a robot knows nothing the readings do not show
  }
}

}  // namespace

TEST_CASE("robots that know only Ω's boundary, or nothing, converge to the known run's cost",
          "[mapping][coverage]") {
  for (const char* name : {"u_shape.json", "l_shape.json", "two_obstacles.json", "fig2b.json",
                           "fig2c.json", "fig2d.json"}) {
    for (const char* known : {"boundary", "none"}) {
      for (const nlohmann::json& range : {nlohmann::json(0.5), nlohmann::json(nullptr)}) {
        INFO(name << ", known " << known << ", range " << range.dump());
        Simulation sim(unknown(name, known, range));
        const CoverageOutcome out = sim.run();
        CHECK(out.converged);
        CHECK(out.known == known);
        REQUIRE(std::isfinite(out.cost_known));
        CHECK(out.cost_ratio() == Approx(1.0).epsilon(0.02));
        CHECK(out.known_fraction > 0.5);  // fig2b: the robots never look behind its wall
        check_inside(*sim.controller().mapping(), out.robots.size());
      }
    }
  }
}

TEST_CASE("with contact sensing nothing is mapped and the planner finds the obstacles (Fig. 4)",
          "[mapping][coverage]") {
  Simulation sim(unknown("u_shape.json", "none", 0.0));
  const CoverageOutcome out = sim.run();
  CHECK(out.converged);
  CHECK(out.known_fraction == 0.0);
  CHECK(out.obstacles_known_min == 0);
  // Targets the map placed in free space, inside the obstacle: found unreachable, settled at
  // the closest point the planner reached, and the run still converges.
  CHECK(out.discoveries > 0);
  CHECK_FALSE(out.planner_failure);
  CHECK(out.cost_ratio() < 1.2);
  // What the robots believe is the bounding box: its cells are larger than Ω's.
  const Mapping& m = *sim.controller().mapping();
  CHECK(m.belief(0).environment->area() == Approx(1.0));
  CHECK(sim.scenario().environment->area() < 0.9);
}

TEST_CASE("with an unlimited range a map holds what is visible from where readings were taken",
          "[mapping]") {
  Simulation sim(unknown("two_obstacles.json", "none", nullptr));
  const CoverageOutcome out = sim.run();
  REQUIRE(out.converged);
  const Mapping& m = *sim.controller().mapping();
  const Environment& env = *sim.scenario().environment;
  const KnownLattice& map = m.merged();
  std::size_t visible = 0;
  for (std::int32_t j = 0; j < map.ny(); ++j) {
    for (std::int32_t i = 0; i < map.nx(); ++i) {
      const Vec2 c = map.centre(i, j);
      bool seen = false, clearly = false;
      for (const Scan& s : m.scans()) {
        if (!env.locate(c)) break;
        seen = seen || env.segment_inside(s.origin, c);
        clearly = clearly ||
                  (env.clear_of_boundary(s.origin, c, 1e-6) && env.boundary_distance(c) > 1e-6);
        if (clearly) break;
      }
      if (map.at(i, j)) CHECK(seen);
      if (clearly) {
        ++visible;
        CHECK(map.at(i, j));
      }
    }
  }
  CHECK(visible > 0.9 * static_cast<double>(m.free_cells().count()));
}

TEST_CASE("decentralized, robots share their maps in their broadcasts, also under loss",
          "[mapping][network]") {
  for (const double loss : {0.0, 0.6, -1.0}) {
    INFO("loss " << loss);
    // -1: no loss, every message delayed by 0.3 s to 0.5 s (three to five broadcasts).
    const nlohmann::json network =
        loss >= 0.0 ? nlohmann::json{{"loss", {{"model", "bernoulli"}, {"p", loss}}}}
                    : nlohmann::json{{"delay", {{"model", "uniform"}, {"min", 0.3}, {"max", 0.5}}}};
    Simulation sim(unknown("two_obstacles.json", "none", 0.5, {{"network", network}}));
    const CoverageOutcome out = sim.run();
    CHECK(out.converged);
    CHECK(out.decentralized);
    const Mapping& m = *sim.controller().mapping();
    check_inside(m, out.robots.size());
    CHECK(out.map_bytes > 0);
    // No broadcast carries more than its limit.
    const double broadcasts = out.sim_time.seconds() / 0.1 + 1.0;
    CHECK(static_cast<double>(out.map_bytes) <=
          broadcasts * static_cast<double>(out.robots.size()) * 1024.0);
    // Every robot learnt the obstacles and most of the area from the others.
    CHECK(out.obstacles_known_min == 2);
    CHECK(out.known_fraction_min > 0.9 * out.known_fraction);
    CHECK(out.cost_ratio() == Approx(1.0).epsilon(0.02));
  }
  // Small messages: readings are cut into parts that fit.
  const nlohmann::json network{{"loss", {{"model", "bernoulli"}, {"p", 0.3}}}};
  Simulation small(unknown("two_obstacles.json", "none", nullptr,
                           {{"network", network}, {"mapping", {{"max_bytes", 100}}}}));
  const CoverageOutcome out = small.run();
  CHECK(out.converged);
  for (const Scan& s : small.controller().mapping()->scans())
    CHECK(s.bytes() <= 100);
}

TEST_CASE("a decentralized mapping run under loss is reproducible", "[mapping][determinism]") {
  const nlohmann::json network{{"loss", {{"model", "bernoulli"}, {"p", 0.3}}}};
  const Scenario s = unknown("u_shape.json", "none", 0.3, {{"network", network}});
  const CoverageOutcome a = Simulation(s).run(), b = Simulation(s).run();
  CHECK(a.fingerprint == b.fingerprint);
  CHECK(a.map_bytes == b.map_bytes);
  CHECK(a.known_fraction_min == b.known_fraction_min);
  // Ω known: the comparison run is the known run itself.
  nlohmann::json j = paper("u_shape.json").json;
  j["sensor"]["range"] = 0.3;
  j["network"] = network;
  CHECK(Simulation(covsim::test::parse_beside_paper(j, "u_shape.json")).run().cost_real ==
        a.cost_known);
}

TEST_CASE("what robots that do not know Ω cannot be told is refused", "[mapping][scenario]") {
  const auto error = [](const char* section, const nlohmann::json& value) {
    nlohmann::json j = paper("u_shape.json").json;
    j["environment"]["known"] = "none";
    if (std::string(section) == "robots.localization")
      j["robots"]["localization"] = value;
    else
      j[section] = value;
    try {
      covsim::test::parse_beside_paper(j, "u_shape.json");
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // A map planner plans on what its robot sensed; on the given map it cannot.
  CHECK(error("planner", {{"type", "visibility_graph"}}) == "no error");
  CHECK_THAT(error("planner", {{"type", "grid_astar"}, {"map", "given"}}),
             Contains("$.planner.map") && Contains("sensed"));
  // straight_line and none plan nothing: they meet the walls the robots have not mapped as
  // they meet the others (a planner told Ω is refused: python/tests/test_components.py).
  CHECK(error("planner", {{"type", "straight_line"}}) == "no error");
  CHECK(error("planner", {{"type", "none"}}) == "no error");
  CHECK_THAT(error("controller", {{"projection", "known"}}), Contains("discover"));
  CHECK_THAT(error("controller", {{"type", "geodesic_lloyd"}}), Contains("geodesic"));
  // Uncertain readings make an occupancy grid; the polygon map needs exact ones.
  CHECK(error("robots.localization", {{"type", "tracking"}}) == "no error");
  CHECK(error("robots.localization", {{"type", "odometry"}}) == "no error");
  CHECK(error("sensor", {{"noise", {{"sigma", 0.01}}}}) == "no error");
  CHECK(error("mapping", {{"model", "polygons"}}) == "no error");
  const auto noisy_polygons = [] {
    nlohmann::json j = paper("u_shape.json").json;
    j["environment"]["known"] = "none";
    j["sensor"]["noise"] = {{"sigma", 0.01}};
    j["mapping"] = {{"model", "polygons"}};
    return j;
  }();
  CHECK_THROWS_WITH(covsim::test::parse_beside_paper(noisy_polygons, "u_shape.json"),
                    Contains("$.mapping.model") && Contains("occupancy"));
  CHECK_THAT(error("mapping", {{"max_bytes", 10}}), Contains("$.mapping.max_bytes"));
  CHECK(error("mapping", {{"spacing", 0.2}}) == "no error");
  // Mapping settings without mapping would be ignored; their defaults may be stated.
  nlohmann::json full = paper("u_shape.json").json;
  full["mapping"] = {{"spacing", 0.2}};
  CHECK_THROWS_WITH(covsim::test::parse_beside_paper(full, "u_shape.json"),
                    Contains("$.mapping") && Contains("environment.known"));
  full["mapping"] = {{"spacing", 0.1}};
  CHECK_NOTHROW(covsim::test::parse_beside_paper(full, "u_shape.json"));
  nlohmann::json bad = paper("u_shape.json").json;
  bad["environment"]["known"] = "partly";
  CHECK_THROWS_WITH(covsim::test::parse_beside_paper(bad, "u_shape.json"),
                    Contains("$.environment.known") && Contains("boundary"));
}

TEST_CASE("map planners plan on what their robots sensed when Ω is not known",
          "[mapping][scenario]") {
  // planner.map "sensed" is implied: the runs converge (every robot at its target or at the
  // projection it found), never leave Ω (the controller checks every motion), and depend on
  // the range, where the same planners on the given map do not.
  for (const char* type : {"grid_astar", "visibility_graph"}) {
    INFO(type);
    const Scenario s = unknown("u_shape.json", "none", 0.3, {{"planner", {{"type", type}}}});
    CHECK(s.coverage.planner.params.text("map") == "sensed");
    const CoverageOutcome near = Simulation(s).run();
    CHECK(near.converged);
    const CoverageOutcome far =
        Simulation(unknown("u_shape.json", "none", nullptr, {{"planner", {{"type", type}}}})).run();
    CHECK(far.converged);
    CHECK(near.fingerprint != far.fingerprint);
    // Ω known, the map a stated choice: sensed runs differ from given ones.
    nlohmann::json j = paper("u_shape.json").json;
    j["planner"] = {{"type", type}, {"map", "sensed"}};
    const CoverageOutcome sensed =
        Simulation(covsim::test::parse_beside_paper(j, "u_shape.json")).run();
    j["planner"] = {{"type", type}};
    const CoverageOutcome given =
        Simulation(covsim::test::parse_beside_paper(j, "u_shape.json")).run();
    CHECK(sensed.converged);
    CHECK(given.converged);
    CHECK(sensed.fingerprint != given.fingerprint);
    // With range noise the map is noisy and the robots settle by touch: the run converges
    // and differs from the noise-free one.
    j["planner"] = {{"type", type}, {"map", "sensed"}};
    j["sensor"]["noise"] = {{"sigma", 0.01}};
    const CoverageOutcome noisy =
        Simulation(covsim::test::parse_beside_paper(j, "u_shape.json")).run();
    CHECK(noisy.converged);
    CHECK(noisy.fingerprint != sensed.fingerprint);
  }
}

TEST_CASE("metrics.csv follows the maps as they grow", "[mapping][metrics]") {
  const nlohmann::json network{{"loss", {{"model", "bernoulli"}, {"p", 0.3}}}};
  Simulation sim(unknown("two_obstacles.json", "none", 0.3, {{"network", network}}));
  MetricsSampler sampler;
  sim.add_observer(&sampler);
  const CoverageOutcome out = sim.run();
  const auto& samples = sampler.samples();
  REQUIRE(samples.size() > 10);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    CHECK(samples[k].known_fraction_min <= samples[k].known_fraction);
    CHECK(samples[k].map_disagreement >= 0.0);
    if (k > 0) CHECK(samples[k].known_fraction >= samples[k - 1].known_fraction);
  }
  CHECK(samples.front().known_fraction < samples.back().known_fraction);
  CHECK(samples.back().known_fraction == out.known_fraction);
  CHECK(samples.back().known_fraction_min == out.known_fraction_min);
  CHECK(samples.back().map_disagreement == out.map_disagreement);
  // Some time a robot's map lagged behind the others'.
  CHECK(std::any_of(samples.begin(), samples.end(),
                    [](const MetricsSample& s) { return s.map_disagreement > 0.0; }));
  CHECK(out.map_bytes_new <= out.map_bytes);
  CHECK(out.map_bytes_new > 0);
}

TEST_CASE("a broadcast packs readings not yet sent in order, then older ones in turn",
          "[mapping][network]") {
  const Scenario s = paper("two_obstacles.json");
  MappingConfig config;
  config.known = KnownEnvironment::none;
  config.max_bytes = 200;
  Mapping m(*s.environment, *s.density, 0.0, 0.3, config, 2, false);
  // Robot 0 takes readings along a line; robot 1 stays where it starts.
  m.start(0, {0.05, 0.05}, SimTime::zero());
  m.start(1, {0.95, 0.95}, SimTime::zero());
  for (int k = 1; k <= 8; ++k)
    m.moved(0, {0.05 + 0.1 * k, 0.05}, 0.1, SimTime::from_seconds(k));
  const std::size_t own = m.scans().size() - 1;  // robot 1 took one
  REQUIRE(own >= 8);
  std::vector<std::uint32_t> sent;
  for (int b = 0; b < 40; ++b) {
    const MapPayload p = m.pack(0);
    REQUIRE(p.scans);
    std::uint32_t bytes = 0;
    for (const std::uint32_t id : *p.scans) {
      bytes += m.scans()[id].bytes();
      sent.push_back(id);
    }
    CHECK(p.bytes == bytes);
    CHECK(p.bytes <= 200);
    CHECK_FALSE(p.scans->empty());
    if (b % 2 == 0) m.merge(1, p);  // every other broadcast lost
  }
  // Each of robot 0's readings once, in the order it took them, before any is sent again.
  std::vector<std::uint32_t> first(sent.begin(), sent.begin() + static_cast<long>(own));
  std::vector<std::uint32_t> expected;
  for (std::uint32_t id = 0; id < m.scans().size(); ++id)
    if (id != 1) expected.push_back(id);  // reading 1 is robot 1's start
  CHECK(first == expected);
  // Then again, in turn: every reading repeated, so robot 1 holds them all despite the losses.
  for (const std::uint32_t id : expected)
    CHECK(std::count(sent.begin(), sent.end(), id) >= 2);
  CHECK(m.lattice(1).common(m.lattice(0)) == m.lattice(0).count());
  CHECK(m.new_bytes_sent() < m.bytes_sent());
}

TEST_CASE("a sensed-map planner enters its goal's wall from the robot's side",
          "[mapping][scenario]") {
  // office, seed 5: robot 28's goal lay on the bottom face of a T's bar, next to the stem;
  // the free cell nearest it lay beyond the stem, where the robot's cells did not reach, and
  // the planner, entering the grid there, declared the goal unreachable (a planner failure at
  // 201.2 s). It enters by a cell the robot's own reach.
  nlohmann::json j = paper("office.json").json;
  j["seed"] = 5;
  j["robots"] = {{"count", 30},
                 {"start", {{"region", {{0.3, 4.2}, {3.2, 4.2}, {3.2, 5.8}, {0.3, 5.8}}}}}};
  j["controller"]["projection"] = "known";
  j["planner"] = {{"type", "grid_astar"}, {"map", "sensed"}};
  j["sensor"]["range"] = 2;
  j["convergence"]["spacing_tolerance"] = 0.01;
  j["convergence"]["position_tolerance"] = nullptr;
  j["convergence"]["virtual_tolerance"] = nullptr;
  const CoverageOutcome out = Simulation(covsim::test::parse_beside_paper(j, "office.json")).run();
  CHECK(out.stop_reason == "converged");
  CHECK(out.sim_time.seconds() > 201.2);
}

TEST_CASE("decentralized, a map planner takes the walls of the readings its robot hears",
          "[mapping][network]") {
  // Each robot senses 0.5 m around its way; the readings it hears from the others put their
  // walls on its planner's map too, so that, lossless, every robot's map ends with nearly every
  // wall any reading showed.
  const auto on_map = [](const PlannerPicture& map, Vec2 p) {
    return std::any_of(map.walls.begin(), map.walls.end(), [&](const auto& w) {
      return segment_distance(p, p, w.first, w.second) <= 1e-9;
    });
  };
  for (const double radius : {0.0, 0.02}) {
    INFO("radius " << radius);
    const nlohmann::json network{{"range", 100.0}};  // every robot hears every other
    nlohmann::json j = paper("two_obstacles.json").json;
    j["environment"]["known"] = "none";
    j["sensor"]["range"] = 0.5;
    j["network"] = network;
    j["planner"] = {{"type", "grid_astar"}};
    j["robots"]["radius"] = radius;
    Simulation sim(covsim::test::parse_beside_paper(j, "two_obstacles.json"));
    const CoverageOutcome out = sim.run();
    CHECK(out.converged);
    CHECK(out.decentralized);
    const auto& scans = sim.controller().mapping()->scans();
    for (std::uint32_t i = 0; i < out.robots.size(); ++i) {
      const PlannerPicture map = sim.controller().robots()[i].planner->picture();
      std::size_t pieces = 0, held = 0;
      for (const Scan& s : scans) {
        for (const VisiblePiece& p : s.pieces) {
          ++pieces;
          // With bodies, the map holds the walls of Ω shrunk by the radius: one lies within
          // the radius of the wall the reading saw.
          const Vec2 mid = 0.5 * (p.a + p.b);
          held +=
              radius == 0.0
                  ? on_map(map, mid)
                  : std::any_of(map.walls.begin(), map.walls.end(), [&](const auto& w) {
                      return segment_distance(mid, mid, w.first, w.second) <= radius * (1.0 + 1e-6);
                    });
        }
      }
      INFO("robot " << i << ": " << held << " of " << pieces << " pieces");
      CHECK(static_cast<double>(held) >= 0.99 * static_cast<double>(pieces));
    }
  }
}

TEST_CASE("uncertain readings map on a log-odds occupancy grid", "[mapping][coverage]") {
  const nlohmann::json tracking{{"type", "tracking"}, {"noise", 0.005}};
  const nlohmann::json noise{{"sigma", 0.01}};
  for (const char* name : {"two_obstacles.json", "u_shape.json"}) {
    INFO(name);
    // Noisy ranges placed by a tracked estimate: the grid, near the known run's cost, with few
    // cells wrong.
    nlohmann::json j = paper(name).json;
    j["environment"]["known"] = "none";
    j["robots"]["localization"] = tracking;
    j["sensor"]["noise"] = noise;
    const CoverageOutcome out = Simulation(covsim::test::parse_beside_paper(j, name)).run();
    CHECK(out.converged);
    CHECK(out.map_model == "occupancy");
    CHECK(out.cost_ratio() == Approx(1.0).epsilon(0.03));
    CHECK(out.map_false_occupied < 0.01);
    CHECK(out.map_false_free < 0.1);
    CHECK(out.known_fraction > 0.9);
    // Exact readings keep the polygon map; on the grid they mark no cell wrong.
    j = paper(name).json;
    j["environment"]["known"] = "none";
    const Scenario exact = covsim::test::parse_beside_paper(j, name);
    CHECK(Simulation(exact).run().map_model == "polygons");
    j["mapping"] = {{"model", "occupancy"}};
    const CoverageOutcome grid = Simulation(covsim::test::parse_beside_paper(j, name)).run();
    CHECK(grid.converged);
    CHECK(grid.map_model == "occupancy");
    CHECK(grid.map_false_occupied == 0.0);
    CHECK(grid.map_false_free == 0.0);
    CHECK(grid.cost_ratio() == Approx(1.0).epsilon(0.03));
  }
}

TEST_CASE("decentralized, the occupancy grids are shared as patches within a message's bytes",
          "[mapping][network]") {
  nlohmann::json j = paper("two_obstacles.json").json;
  j["environment"]["known"] = "none";
  j["sensor"]["noise"] = {{"sigma", 0.01}};
  j["sensor"]["range"] = 0.5;
  j["network"] = {{"loss", {{"model", "bernoulli"}, {"p", 0.3}}}};
  j["mapping"] = {{"max_bytes", 300}, {"compare_known", false}};
  const Scenario s = covsim::test::parse_beside_paper(j, "two_obstacles.json");
  Simulation a(s), b(s);
  const CoverageOutcome out = a.run();
  CHECK(out.converged);
  CHECK(out.map_model == "occupancy");
  CHECK(out.map_bytes > 0);
  CHECK(out.known_fraction_min > 0.5);
  CHECK(b.run().fingerprint == out.fingerprint);
  const Mapping& m = *a.controller().mapping();
  REQUIRE(m.grid());
  // Every reading was cut into patches that fit one message.
  CHECK(m.scans().size() > 0);
  CHECK(m.disagreement() >= 0.0);
}
