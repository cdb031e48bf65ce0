#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "scenarios/json_reader.hpp"
#include "scenarios/random_environment.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_description.hpp"
#include "scenarios/scenario_error.hpp"

using namespace covsim;
namespace fs = std::filesystem;

namespace {
fs::path write(const std::string& name, const std::string& text) {
  // One folder per process: ctest runs test cases in parallel.
  const fs::path dir =
      fs::temp_directory_path() / ("covsim-scenario-tests-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

const std::string kSquare =
    R"("environment": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]], "holes": [[[1, 1], [2, 1], [2, 2], [1, 2]]]})";

void expect_error(const std::string& body, const std::string& fragment) {
  const fs::path f = write("bad.json", body);
  try {
    load_scenario(f);
    FAIL("accepted: " << body);
  } catch (const ScenarioError& e) {
    const std::string msg = e.what();
    CHECK_THAT(msg, Catch::StartsWith(f.string() + ":"));
    CHECK_THAT(msg, Catch::Contains(fragment));
  }
}
}  // namespace

TEST_CASE("a minimal scenario loads", "[scenario]") {
  const fs::path f = write(
      "ok.json",
      "{" + kSquare +
          R"(, "density": {"type": "uniform"}, "robots": {"positions": [[0.5, 0.5], [3, 3]]}, "seed": 7})");
  const Scenario s = load_scenario(f);
  CHECK(s.environment->area() == Approx(15.0));
  CHECK(s.robot_positions.size() == 2);
  CHECK(s.seed == 7u);
  CHECK(s.density->is_uniform());
  // The neighbour acquisition before the first loop 1: one broadcast period, then up to ten.
  CHECK(s.coverage.network.acquire_time() == s.coverage.network.broadcast_period);
  CHECK(s.coverage.network.acquire_deadline().ns() ==
        10 * s.coverage.network.broadcast_period.ns());
  const Scenario t = load_scenario(write(
      "acquire.json",
      "{" + kSquare +
          R"(, "density": {"type": "uniform"}, "network": {"acquire": 0.5, "acquire_timeout": 3}})"));
  CHECK(t.coverage.network.acquire_time() == SimTime::from_seconds(0.5));
  CHECK(t.coverage.network.acquire_deadline() == SimTime::from_seconds(3.0));
}

TEST_CASE("scenario errors name the file, the JSON path and what was expected", "[scenario]") {
  const std::string d = R"("density": {"type": "uniform"})";
  expect_error("{" + kSquare + ", " + d + R"(, "extra": 1})", "$.extra: unknown key \"extra\"");
  expect_error("{" + d + "}", "$: missing required key \"environment\"");
  expect_error("{" + kSquare + "}", "$: missing required key \"density\"");
  expect_error(R"({"environment": {"outer": [[0, 0], [1, 0], [1, "x"]]}, )" + d + "}",
               "$.environment.outer[2][1]: expected a number, found a string");
  expect_error(R"({"environment": {"outer": [[0, 0], [1, 0], [1]]}, )" + d + "}",
               "$.environment.outer[2]: expected a point [x, y]");
  expect_error(R"({"environment": {"outer": [[0, 0], [2, 2], [2, 0], [0, 2]]}, )" + d + "}",
               "$.environment.outer: outer ring: is self-intersecting");
  expect_error(
      R"({"environment": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]], "holes": [[[1, 1], [2, 1], [2, 2], [1, 2]], [[3, 3], [5, 3], [5, 5]]]}, )" +
          d + "}",
      "$.environment.holes[1]: hole 1: is not strictly inside");
  expect_error("{" + kSquare + R"(, "density": {"type": "fancy"}})",
               "$.density.type: expected one of \"uniform\", \"gaussian_mixture\", \"raster\", "
               "found \"fancy\"");
  expect_error(
      "{" + kSquare +
          R"(, "density": {"type": "gaussian_mixture", "components": [{"mean": [1, 1], "sigma": -1, "weight": 1}]}})",
      "$.density.components[0].sigma: expected a number > 0 m, found -1");
  expect_error(
      "{" + kSquare +
          R"(, "density": {"type": "gaussian_mixture", "components": [{"mean": [1, 1], "sigma": 1, "weight": 1, "colour": 2}]}})",
      "$.density.components[0].colour: unknown key");
  expect_error("{" + kSquare + R"(, "density": {"type": "gaussian_mixture", "components": []}})",
               "$.density: the density has no mass");
  expect_error("{" + kSquare + ", " + d + R"(, "robots": {"positions": [[0.5, 0.5], [1.5, 1.5]]}})",
               "$.robots.positions[1]: robot at (1.5, 1.5) is not in the environment");
  expect_error("{" + kSquare + ", " + d + R"(, "robots": {"positions": [[0.5, 0.5], [0.5, 0.5]]}})",
               "robots 0 and 1 start at the same position");
  expect_error("{" + kSquare + ", " + d + R"(, "seed": -3})",
               "$.seed: expected a non-negative integer");
  expect_error("{" + kSquare + ", " + d + R"(, "seed": 1.5})",
               "$.seed: expected a non-negative integer");
  expect_error("{\n" + kSquare + ",\n" + d + ",,}", "bad.json:3:");
  expect_error("[1, 2]", "$: expected an object, found an array");
  expect_error("{" + kSquare + ", " + d + R"(, "sensor": {"range": -1}})",
               "$.sensor.range: expected a number >= 0 m, found -1");
  expect_error("{" + kSquare + ", " + d + R"(, "sensor": {"dropout": 1.5}})",
               "$.sensor.dropout: expected a number >= 0 and <= 1, found 1.5");
  expect_error("{" + kSquare + ", " + d + R"(, "sensor": {"noise": {"sd": 1}}})",
               "$.sensor.noise.sd: unknown key");
  expect_error("{" + kSquare + ", " + d + R"(, "network": {"loss": {"model": "bernoulli"}}})",
               "$.network.loss: missing required key \"p\"");
  expect_error(
      "{" + kSquare + ", " + d + R"(, "network": {"loss": {"model": "bernoulli", "p": 2}}})",
      "$.network.loss.p: expected a number >= 0 and <= 1, found 2");
  expect_error("{" + kSquare + ", " + d +
                   R"(, "network": {"delay": {"model": "uniform", "min": 0.2, "max": 0.1}}})",
               "$.network.delay.max: expected max >= min");
  expect_error("{" + kSquare + ", " + d + R"(, "network": {"delay": {"model": "gamma"}}})",
               "$.network.delay.model: expected one of");
  expect_error("{" + kSquare + ", " + d + R"(, "network": {"acquire": -1}})",
               "$.network.acquire: expected a number >= 0 and <= 1000000 s, found -1");
  expect_error(
      "{" + kSquare + ", " + d + R"(, "network": {"acquire_timeout": 1e9}})",
      "$.network.acquire_timeout: expected a number >= 0 and <= 1000000 s, found 1000000000");
  expect_error("{" + kSquare + ", " + d + R"(, "loops": {"loop1_period": 1}})",
               "$.loops.loop1_period: loop1_period applies to");
  expect_error("{" + kSquare + ", " + d + R"(, "loops": {"mode": "periodic", "loop2_period": 0}})",
               "$.loops.loop2_period: expected a number >= 0.0001 and <= 1000000 s, found 0");
}

TEST_CASE("planners and controllers with their parameters", "[scenario]") {
  const std::string d = R"("density": {"type": "uniform"})";
  const fs::path f =
      write("planners.json",
            "{" + kSquare + ", " + d +
                R"(, "planner": {"type": "potential_field", "influence": 0.3, "stall_window": 7},
               "controller": {"type": "geodesic_lloyd", "resolution": 0.05, "gain": 0.5}})");
  const Scenario s = load_scenario(f);
  CHECK(s.coverage.planner.type == "potential_field");
  CHECK(s.coverage.planner.params.number("influence") == 0.3);
  CHECK(s.coverage.planner.params.integer("stall_window") == 7u);
  CHECK(s.coverage.planner.params.number("repulsive_gain") == 1.0);  // its default
  CHECK(s.coverage.law.type == "geodesic_lloyd");
  CHECK(s.coverage.law.params.number("resolution") == 0.05);
  CHECK(s.coverage.law.params.number("gain") == 0.5);
  for (const char* type : {"tangent_bug", "grid_astar", "visibility_graph", "straight_line"}) {
    const fs::path g = write(
        "planner.json", "{" + kSquare + ", " + d + R"(, "planner": {"type": ")" + type + R"("}})");
    CHECK(load_scenario(g).coverage.planner.type == type);
  }
  expect_error("{" + kSquare + ", " + d + R"(, "planner": {"type": "rrt"}})",
               "$.planner.type: expected one of");
  expect_error("{" + kSquare + ", " + d + R"(, "planner": {"type": "tangent_bug", "range": 1}})",
               "$.planner.range: unknown key \"range\" for planner \"tangent_bug\"");
  // A parameter of another planner type is refused with where it belongs...
  expect_error(
      "{" + kSquare + ", " + d + R"(, "planner": {"type": "tangent_bug", "resolution": 0.1}})",
      "$.planner.resolution: \"resolution\" is not a parameter of planner \"tangent_bug\" (it "
      "is one of grid_astar");
  // ... and accepted in that type's own section, checked there, for a sweep over types.
  const Scenario sections = load_scenario(
      write("sections.json",
            "{" + kSquare + ", " + d +
                R"(, "planner": {"type": "tangent_bug", "grid_astar": {"resolution": 0.1},
                              "potential_field": {"influence": 0.2}}})"));
  CHECK(sections.coverage.planner.type == "tangent_bug");
  const Scenario picked = load_scenario(
      write("picked.json",
            "{" + kSquare + ", " + d +
                R"(, "planner": {"type": "grid_astar", "grid_astar": {"resolution": 0.1}}})"));
  CHECK(picked.coverage.planner.params.number("resolution") == 0.1);
  expect_error("{" + kSquare + ", " + d +
                   R"(, "planner": {"type": "tangent_bug", "grid_astar": {"resolution": -1}}})",
               "$.planner.grid_astar.resolution: expected a number > 0");
  expect_error("{" + kSquare + ", " + d +
                   R"(, "planner": {"type": "grid_astar", "resolution": 0.1,
                      "grid_astar": {"resolution": 0.2}}})",
               "$.planner.grid_astar.resolution: \"resolution\" is set twice");
  expect_error(
      "{" + kSquare + ", " + d + R"(, "planner": {"type": "grid_astar", "resolution": 0}})",
      "$.planner.resolution: expected a number > 0 m, found 0");
  expect_error(
      "{" + kSquare + ", " + d + R"(, "planner": {"type": "grid_astar", "resolution": 1e-6}})",
      "$.planner.resolution: resolution too fine");
  expect_error(
      "{" + kSquare + ", " + d + R"(, "planner": {"type": "potential_field", "stall_window": 0}})",
      "$.planner.stall_window: expected a whole number >= 1");
  expect_error("{" + kSquare + ", " + d + R"(, "controller": {"type": "voronoi"}})",
               "$.controller.type: expected one of");
  expect_error("{" + kSquare + ", " + d + R"(, "controller": {"type": "euclidean_lloyd", "k": 1}})",
               "$.controller.k: unknown key");
  expect_error(
      "{" + kSquare + ", " + d + R"(, "controller": {"type": "geodesic_lloyd", "gain": 2}})",
      "$.controller.gain: expected a number > 0 and <= 1, found 2");
  // Without a type the controller is the paper's, whose parameters these are not.
  expect_error("{" + kSquare + ", " + d + R"(, "controller": {"resolution": 0.1}})",
               "$.controller.resolution: \"resolution\" is not a parameter of coverage law "
               "\"virtual_generators\"");
}

TEST_CASE("tolerances may be a fraction of the robots' spacing", "[scenario]") {
  const std::string d = R"("density": {"type": "uniform"})";
  // 15 m² shared by two robots: a spacing of √7.5.
  const std::string robots = R"(, "robots": {"positions": [[0.5, 0.5], [3, 3]]})";
  const Scenario s =
      load_scenario(write("t1.json", "{" + kSquare + ", " + d + robots +
                                         R"(, "convergence": {"spacing_tolerance": 0.01}})"));
  REQUIRE(s.robot_positions.size() == 2);
  const auto tol = describe_scenario(s)["convergence"];
  CHECK(tol["position_tolerance"].get<double>() == Approx(0.01 * std::sqrt(7.5)).epsilon(1e-12));
  CHECK(tol["virtual_tolerance"].get<double>() == Approx(0.01 * std::sqrt(7.5)).epsilon(1e-12));
  // An explicit tolerance wins over the fraction.
  const Scenario both = load_scenario(
      write("t2.json",
            "{" + kSquare + ", " + d + robots +
                R"(, "convergence": {"spacing_tolerance": 0.01, "position_tolerance": 0.5}})"));
  CHECK(describe_scenario(both)["convergence"]["position_tolerance"].get<double>() == 0.5);
  expect_error("{" + kSquare + ", " + d + R"(, "convergence": {"spacing_tolerance": 2}})",
               "$.convergence.spacing_tolerance: expected a fraction of the robots' spacing");
  expect_error("{" + kSquare + ", " + d + R"(, "convergence": {"spacing_tolerance": 0}})",
               "$.convergence.spacing_tolerance: expected a fraction of the robots' spacing > 0 "
               "and <= 1, found 0");
}

TEST_CASE("the projection policy belongs to the controller section, whatever its type",
          "[scenario]") {
  const std::string d = R"("density": {"type": "uniform"})";
  CHECK(load_scenario(write("p0.json", "{" + kSquare + ", " + d + "}")).coverage.projection ==
        ProjectionPolicy::discover);
  const Scenario known = load_scenario(
      write("p1.json", "{" + kSquare + ", " + d + R"(, "controller": {"projection": "known"}})"));
  CHECK(known.coverage.projection == ProjectionPolicy::known);
  CHECK(known.coverage.law.type == "virtual_generators");
  const Scenario geodesic = load_scenario(
      write("p2.json", "{" + kSquare + ", " + d +
                           R"(, "controller": {"type": "geodesic_lloyd", "projection": "known",
                                               "gain": 0.5}})"));
  CHECK(geodesic.coverage.projection == ProjectionPolicy::known);
  CHECK(geodesic.coverage.law.params.number("gain") == 0.5);
  CHECK(describe_scenario(known)["controller"]["projection"] == "known");
  CHECK(describe_scenario(geodesic)["controller"]["projection"] == "known");
  expect_error("{" + kSquare + ", " + d + R"(, "controller": {"projection": "guess"}})",
               "$.controller.projection: expected one of");
  expect_error("{" + kSquare + ", " + d + R"(, "controller": {"projection": 1}})",
               "$.controller.projection: expected");
}

TEST_CASE("raster densities load relative to the scenario file", "[scenario]") {
  write("ramp.csv", "3,4\n1,2\n");
  const fs::path f = write(
      "raster.json",
      "{" + kSquare +
          R"(, "density": {"type": "raster", "file": "ramp.csv", "extent": [[0, 0], [4, 4]]}})");
  const Scenario s = load_scenario(f);
  CHECK((*s.density)({1, 3.5}) == 3.0);
  expect_error(
      "{" + kSquare +
          R"(, "density": {"type": "raster", "file": "ramp.csv", "extent": [[0, 0], [3, 4]]}})",
      "$.density.extent: the raster must cover");
  expect_error(
      "{" + kSquare +
          R"(, "density": {"type": "raster", "file": "missing.csv", "extent": [[0, 0], [4, 4]]}})",
      "$.density.file: ");
  expect_error(
      "{" + kSquare +
          R"(, "density": {"type": "raster", "file": "ramp.txt", "extent": [[0, 0], [4, 4]]}})",
      "$.density.file: expected a .csv or .pgm file");
}

TEST_CASE("random environments are valid scenarios, the same for the same seed", "[scenario]") {
  std::size_t with_holes = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    RandomEnvironmentSpec spec;
    spec.seed = seed;
    const nlohmann::ordered_json a = random_environment(spec);
    CHECK(a == random_environment(spec));
    const Scenario s = parse_scenario(nlohmann::json::parse(a.dump()), "random", ".");
    CHECK(s.robot_positions.size() == spec.robots);
    CHECK(s.environment->hole_count() <= spec.holes);
    with_holes += s.environment->hole_count() > 0 ? 1 : 0;
    CHECK(s.seed == seed);
    spec.seed = seed + 100;
    CHECK(a["environment"] != random_environment(spec)["environment"]);
  }
  CHECK(with_holes >= 15);
  RandomEnvironmentSpec bad;
  bad.robots = 0;
  CHECK_THROWS_AS(random_environment(bad), std::invalid_argument);
}

TEST_CASE("random environments hold ten thousand robots at constant density", "[scenario]") {
  // 700 robots used to be the most any size held: their distance did not shrink with N.
  for (std::uint32_t n : {1000u, 10000u}) {
    RandomEnvironmentSpec spec;
    spec.robots = n;
    spec.size = 0.4 * std::sqrt(static_cast<double>(n));  // about the same density
    const nlohmann::ordered_json a = random_environment(spec);
    const Scenario s = parse_scenario(nlohmann::json::parse(a.dump()), "random", ".");
    REQUIRE(s.robot_positions.size() == n);
    // Apart by at least half the constant-density spacing (checked on a sorted sweep).
    const double apart = 0.5 * std::sqrt(s.environment->area() / n) * (1 - 1e-12);
    std::vector<Vec2> p = s.robot_positions;
    std::sort(p.begin(), p.end(), [](Vec2 u, Vec2 v) { return u.x < v.x; });
    double closest = INFINITY;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size() && p[j].x - p[i].x < apart; ++j)
        closest = std::min(closest, distance(p[i], p[j]));
    CHECK(closest >= apart);
    for (Vec2 q : p)
      CHECK(s.environment->contains(q));
  }
}

TEST_CASE("robots drawn per seed: each seed a deployment, the same on every load",
          "[scenario][deployment]") {
  const std::string d = R"("density": {"type": "uniform"})";
  const auto load = [&](const std::string& robots, std::uint64_t seed) {
    return load_scenario(write("drawn.json", "{" + kSquare + ", " + d + R"(, "robots": )" + robots +
                                                 R"(, "seed": )" + std::to_string(seed) + "}"));
  };
  const std::string uniform = R"({"count": 12, "start": {"uniform": true}})";
  const Scenario a = load(uniform, 1), again = load(uniform, 1), b = load(uniform, 2);
  REQUIRE(a.robot_positions.size() == 12);
  CHECK(a.robot_positions == again.robot_positions);
  CHECK(a.robot_positions != b.robot_positions);
  for (Vec2 p : a.robot_positions)
    CHECK(a.environment->contains(p));
  // The default separation: 1/20 of sqrt(area / count).
  const double sep = 0.05 * std::sqrt(15.0 / 12.0);
  for (std::size_t i = 0; i < 12; ++i) {
    for (std::size_t j = 0; j < i; ++j)
      CHECK(distance(a.robot_positions[i], a.robot_positions[j]) >= sep);
  }
  // A cluster in a corner, as in the paper's figures, and a region.
  const Scenario c =
      load(R"({"count": 5, "start": {"cluster": {"center": [0.3, 3.7], "radius": 0.25}},
               "separation": 0.05})",
           3);
  for (Vec2 p : c.robot_positions)
    CHECK(distance(p, {0.3, 3.7}) <= 0.25);
  const Scenario r =
      load(R"({"count": 6, "start": {"region": [[2.5, 0], [4, 0], [4, 4], [2.5, 4]]}})", 3);
  for (Vec2 p : r.robot_positions)
    CHECK(p.x >= 2.5);
  // Jitter moves given robots, by seed.
  const std::string given = R"({"positions": [[0.5, 0.5], [3, 3]], "jitter": 0.05})";
  const Scenario j1 = load(given, 1), j2 = load(given, 2);
  CHECK(j1.robot_positions != j2.robot_positions);
  CHECK(distance(j1.robot_positions[0], {0.5, 0.5}) < 0.5);
  // Another seed redraws (as a sweep's seeds and covsim run --seed do).
  CHECK(with_seed(a, 2).robot_positions == b.robot_positions);
  CHECK(with_seed(a, 1).robot_positions == a.robot_positions);
}

TEST_CASE("drawn robots and density means are checked", "[scenario][deployment]") {
  const std::string d = R"("density": {"type": "uniform"})";
  const auto robots = [&](const std::string& r, const std::string& fragment,
                          const std::string& seed = R"(, "seed": 1)") {
    expect_error("{" + kSquare + ", " + d + R"(, "robots": )" + r + seed + "}", fragment);
  };
  robots(R"({"positions": [[0.5, 0.5]], "count": 3})",
         "$.robots: expected \"positions\" or \"count\"");
  robots(R"({"count": 3})", "$.robots: missing required key \"start\"");
  robots(R"({"count": 3, "start": {}})",
         "$.robots.start: expected exactly one of \"uniform\", \"region\" and \"cluster\"");
  robots(R"({"count": 3, "start": {"uniform": true, "cluster": {"center": [0, 0], "radius": 1}}})",
         "expected exactly one of");
  robots(R"({"count": 0, "start": {"uniform": true}})",
         "$.robots.count: expected 1 to 100000 robots");
  robots(R"({"count": 3, "start": {"cluster": {"center": [3, 3], "radius": -1}}})",
         "$.robots.start.cluster.radius: expected a positive number");
  robots(R"({"count": 50, "start": {"cluster": {"center": [0.5, 0.5], "radius": 0.1}},
            "separation": 0.1})",
         "$.robots.start: placed");
  robots(R"({"positions": [[0.5, 0.5]], "start": {"uniform": true}})",
         "$.robots.start: \"start\" goes with \"count\"");
  robots(R"({"count": 3, "start": {"uniform": true}, "jitter": 0.1})",
         "$.robots.jitter: \"jitter\" goes with \"positions\"");
  robots(R"({"count": 3, "start": {"region": [[0, 0], [1, 1], [1, 0], [0, 1]]}})",
         "$.robots.start.region: expected a simple polygon");
  robots(R"({"count": 3, "start": {"uniform": true}})", "need the scenario's \"seed\"", "");
  // A Gaussian mean drawn per seed needs a seed too; with one, it lands in Ω.
  const std::string mixture =
      R"("density": {"type": "gaussian_mixture", "components": [{"mean": null, "sigma": 0.5, "weight": 1}]})";
  expect_error("{" + kSquare + ", " + mixture + "}", "a null mean is drawn from the scenario's");
  const Scenario s1 =
      load_scenario(write("m.json", "{" + kSquare + ", " + mixture + R"(, "seed": 1})"));
  const Scenario s2 =
      load_scenario(write("m.json", "{" + kSquare + ", " + mixture + R"(, "seed": 2})"));
  CHECK((*s1.density)({0.5, 0.5}) != (*s2.density)({0.5, 0.5}));
}

TEST_CASE("JSON is read strictly: duplicate keys, deep nesting, huge numbers, directories",
          "[scenario]") {
  // A duplicate key is an error at its object's path, wherever it is.
  expect_error("{" + kSquare + R"(, "seed": 1, "seed": 2})", "$: duplicate key \"seed\"");
  expect_error("{" + kSquare + R"(, "robots": {"count": 2, "count": 3}})",
               "$.robots: duplicate key \"count\"");
  expect_error(R"({"environment": {"outer": [[0, 0], [4, 0], [4, 4], {"x": 1, "x": 2}]}})",
               "$.environment.outer[3]: duplicate key \"x\"");
  // Keys repeated in different objects are fine.
  CHECK_NOTHROW(load_scenario(write("ok.json", "{" + kSquare + R"(, "density": {"type": "uniform"},
      "robots": {"positions":
      [[0.5, 0.5]]}, "sensor": {"range": 1}, "planner": {"type": "tangent_bug"}})")));
  // Nesting is bounded (100 000 levels used to overflow the stack).
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  expect_error(deep, "JSON nested deeper than 256 levels");
  CHECK_NOTHROW(parse_json(std::string(200, '[') + std::string(200, ']'), "nest"));
  // A number beyond a double's range is named with its place.
  expect_error("{\n" + kSquare + R"(, "seed": 1,
    "sensor": {"range": 1e999}})",
               ":3:25: the number 1e999 is out of a double's range");
  // A directory is not malformed JSON.
  const fs::path dir = write("x.json", "{}").parent_path() / "a-folder";
  fs::create_directories(dir);
  CHECK_THROWS_WITH(load_scenario(dir), Catch::Contains("is a directory, not a JSON file"));
}

TEST_CASE("sizes and periods beyond the stated limits are refused, naming the place",
          "[scenario]") {
  const std::string rest = R"(, "density": {"type": "uniform"}, "seed": 1})";
  // A hole's side of 1e-9 m in a unit square, an Ω 1e-200 m across, coordinates of 1e77.
  expect_error(R"({"environment": {"outer": [[0, 0], [1, 0], [1, 1], [0, 1]], "holes":
      [[[0.5, 0.5], [0.500000001, 0.5], [0.500000001, 0.500000001], [0.5, 0.500000001]]]})" +
                   rest,
               "$.environment.holes[0][0]: the edge from this vertex is 1e-09 m long");
  expect_error(
      R"({"environment": {"outer": [[0, 0], [1e-200, 0], [1e-200, 1e-200], [0, 1e-200]]})" + rest,
      "$.environment.outer: the environment is 1.41421e-200 m across");
  expect_error(R"({"environment": {"outer": [[0, 0], [1e77, 0], [1e77, 1e77], [0, 1e77]]})" + rest,
               "$.environment.outer[1]: coordinates beyond ±1e+06 m are not supported");
  // Periods below 1e-4 s, and runs of more than 1e8 motion steps.
  expect_error(
      "{" + kSquare + R"(, "density": {"type": "uniform"}, "loops": {"loop2_period": 1e-9}})",
      "$.loops.loop2_period: expected a number >= 0.0001 and <= 1000000 s, found 1e-09");
  expect_error(
      "{" + kSquare + R"(, "density": {"type": "uniform"}, "loops": {"loop2_period": 0.001},
      "convergence": {"max_time": 200000}})",
      "$.convergence.max_time: max_time 200000 s at a loop-2 period of 0.001 s");
  // ... unless the limit is raised deliberately.
  CHECK_NOTHROW(load_scenario(write("long.json", "{" + kSquare + R"(, "density": {"type":
      "uniform"}, "loops": {"loop2_period": 0.001}, "convergence": {"max_time": 200000},
      "limits": {"motion_steps": 3e8}})")));
  // A trajectory.csv of more than 2e7 rows: refused, unless thinned or the limit raised.
  const std::string many = "{" + kSquare + R"(, "density": {"type": "uniform"},
      "robots": {"count": 100, "start": {"uniform": true}}, "seed": 1,
      "convergence": {"max_time": 30000})";
  expect_error(many + "}",
               "$.convergence.max_time: 100 robots until max_time 30000 s write up to 3e+07 rows "
               "of trajectory.csv");
  CHECK_NOTHROW(
      load_scenario(write("thin.json", many + R"(, "recording": {"trajectory_period": 1}})")));
  CHECK_NOTHROW(
      load_scenario(write("raised.json", many + R"(, "limits": {"trajectory_rows": 1e8}})")));
  expect_error(many + R"(, "limits": {"trajectory_rows": -1}})",
               "$.limits.trajectory_rows: expected a number > 0 rows, found -1");
  // At the limits themselves: accepted.
  CHECK_NOTHROW(load_scenario(write("big.json", R"({"environment": {"outer": [[-1e6, -1e6],
      [1e6, -1e6], [1e6, 1e6], [-1e6, 1e6]]}, "density": {"type": "uniform"}})")));
}
