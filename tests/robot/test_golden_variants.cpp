// Golden fingerprints of variants beyond the paper's ideal-network scenarios: lossy and
// delayed networks of every model, range and line-of-sight limits, noisy and sampled
// sensors, every planner and controller, non-uniform densities, and bodies, avoidance,
// kinematics, localization and robots that map an unknown Ω. A change that alters
// any of these runs changes its fingerprint: update them deliberately and say why in the
// commit message. A refactor must leave every one unchanged.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <fstream>

#include "core/fingerprint.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_description.hpp"
#include "sim/coverage_run.hpp"

using namespace covsim;

namespace {
struct Variant {
  const char* name;
  const char* scenario;  // in scenarios/
  const char* patch;     // JSON merge patch applied to it
  const char* fingerprint;
};

// Short runs: every variant stops by max_time 40 s at the latest.
const Variant kVariants[] = {
    {"bernoulli loss, decentralized", "u_shape.json",
     R"({"network": {"loss": {"model": "bernoulli", "p": 0.2}}})", "83cc74dee8f54a42"},
    {"gilbert-elliott loss, uniform delay, random phase, staleness", "two_obstacles.json",
     R"({"network": {"loss": {"model": "gilbert_elliott", "p_good_to_bad": 0.1,
         "p_bad_to_good": 0.4, "loss_good": 0.05, "loss_bad": 0.7},
         "delay": {"model": "uniform", "min": 0.01, "max": 0.2}, "random_phase": true,
         "staleness": 1.0, "broadcast_period": 0.2}})",
     "c32a11edffb43978"},
    {"distance loss, exponential delay, range, line of sight", "two_obstacles.json",
     R"({"network": {"range": 0.6, "line_of_sight": true,
         "loss": {"model": "distance", "p_min": 0.05, "d_max": 0.8, "exponent": 2},
         "delay": {"model": "exponential", "base": 0.02, "mean": 0.05}}})",
     "84cea6e823aa5e18"},
    {"lognormal delay, periodic loop 1", "u_shape.json",
     R"({"network": {"delay": {"model": "lognormal", "base": 0.01, "mu": -3, "sigma": 0.5}},
         "loops": {"mode": "periodic", "loop1_period": 0.5}})",
     "b3df246d4b85c7ed"},
    {"sampled, noisy sensor with dropout, short range", "two_obstacles.json",
     R"({"sensor": {"range": 0.2, "period": 0.3, "noise": {"sigma": 0.005}, "dropout": 0.2}})",
     "7452a586b1ebac49"},
    {"contact sensor", "fig2c.json", R"({"sensor": {"range": 0}})", "6214c5431dda41d9"},
    {"potential field", "u_shape.json",
     R"({"planner": {"type": "potential_field", "influence": 0.2, "stall_window": 30}})",
     "e945dd99bdb374f0"},
    {"grid A*", "two_obstacles.json", R"({"planner": {"type": "grid_astar", "resolution": 0.02}})",
     "c6e7b4d2718513c4"},
    {"visibility graph", "office.json",
     R"({"planner": {"type": "visibility_graph"}, "convergence": {"max_time": 40}})",
     "872616acf1ce24f9"},
    {"straight line", "fig2d.json", R"({"planner": {"type": "straight_line"}})",
     "72addbae74c93804"},
    {"euclidean Lloyd", "fig2b.json", R"({"controller": {"type": "euclidean_lloyd"}})",
     "2dc065c2abe1bf9b"},
    {"geodesic Lloyd", "fig2b.json",
     R"({"controller": {"type": "geodesic_lloyd", "resolution": 0.05, "gain": 0.5}})",
     "f95a9d13833bb04c"},
    {"geodesic Lloyd, decentralized", "u_shape.json",
     R"({"controller": {"type": "geodesic_lloyd", "resolution": 0.05},
         "network": {"loss": {"model": "bernoulli", "p": 0.1}}})",
     "8c985ef10f6f579d"},
    {"gaussian mixture density", "l_shape.json",
     R"({"density": {"type": "gaussian_mixture", "floor": 0.1,
         "components": [{"mean": [0.3, 0.7], "sigma": 0.2, "weight": 2},
                        {"mean": [0.8, 0.2], "sigma": 0.3, "weight": 1}]}})",
     "aefe3442e99f6118"},
    {"bilinear raster density", "u_shape.json",
     R"({"density": {"type": "raster", "file": "RASTER", "extent": [[0, 0], [1, 1]],
         "interpolation": "bilinear"}})",
     "ce8c6d238b8a0be3"},
    {"office, decentralized under loss, periodic", "office.json",
     R"({"network": {"loss": {"model": "bernoulli", "p": 0.1}},
         "loops": {"mode": "periodic", "loop1_period": 1.0}, "convergence": {"max_time": 40}})",
     "1346a52f9d4f5631"},
    {"e-puck: bodies, ORCA, differential drive, tracking with latency", "epuck_u_shape.json", "{}",
     "cf47376a435a7527"},
    {"bodies, ORCA, unicycle with acceleration limits", "two_obstacles.json",
     R"({"robots": {"radius": 0.03, "avoidance": {"type": "orca"},
         "kinematics": {"type": "unicycle", "acceleration": 0.5}}})",
     "efac030aec476cd7"},
    {"odometry drift, Ω known", "u_shape.json",
     R"({"robots": {"localization": {"type": "odometry", "drift": 0.01}},
         "controller": {"projection": "known"}})",
     "c10b429d67160e1e"},
    {"tracking with drift, decentralized under loss", "two_obstacles.json",
     R"({"robots": {"localization": {"type": "tracking", "noise": 0.003, "drift": 0.002,
         "latency": 0.05, "compensated": false}},
         "network": {"loss": {"model": "bernoulli", "p": 0.2}},
         "controller": {"projection": "known"}})",
     "20d9850f64057ef6"},
    {"unknown Ω (none), short range, one shared map", "u_shape.json",
     R"({"environment": {"known": "none"}, "sensor": {"range": 0.3},
         "mapping": {"compare_known": false}})",
     "3d59140ac9d4e822"},
    {"unknown holes (boundary), maps shared under loss in small messages", "two_obstacles.json",
     R"({"environment": {"known": "boundary"}, "sensor": {"range": 0.5},
         "network": {"loss": {"model": "bernoulli", "p": 0.3}},
         "mapping": {"max_bytes": 200, "compare_known": false}})",
     "33430926bfac656a"},
    {"office unknown (none), decentralized under loss", "office.json",
     R"({"environment": {"known": "none"}, "sensor": {"range": 2},
         "network": {"loss": {"model": "bernoulli", "p": 0.1}},
         "mapping": {"compare_known": false}, "convergence": {"max_time": 40}})",
     "bf7be31ac8d5beaf"},
};

Scenario variant(const Variant& v) {
  const std::string dir = std::string(COVSIM_SOURCE_DIR) + "/scenarios/";
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dir + v.scenario));
  std::string patch = v.patch;
  const std::string raster = std::string(COVSIM_SOURCE_DIR) + "/tests/data/ramp10.csv";
  if (const auto at = patch.find("RASTER"); at != std::string::npos) patch.replace(at, 6, raster);
  j.merge_patch(nlohmann::json::parse(patch));
  if (!j.contains("convergence") || !j["convergence"].contains("max_time"))
    j["convergence"]["max_time"] = 40;
  return parse_scenario(j, v.name, dir);
}
}  // namespace

TEST_CASE("network, sensor, planner, controller and density variants keep their fingerprints",
          "[golden]") {
  for (const Variant& v : kVariants) {
    INFO(v.name);
    const CoverageOutcome out = run_coverage(variant(v));
    CHECK(Fingerprint::to_hex(out.fingerprint) == v.fingerprint);
  }
}

TEST_CASE("a described scenario loads back to the same run", "[describe]") {
  // covsim describe: every default written out, derived ones computed; loading that gives
  // the same run, fingerprint for fingerprint, for every variant and paper scenario.
  std::vector<Scenario> all;
  for (const Variant& v : kVariants)
    all.push_back(variant(v));
  for (const char* name : {"l_shape.json", "u_shape.json", "two_obstacles.json", "fig2b.json"}) {
    const std::string dir = std::string(COVSIM_SOURCE_DIR) + "/scenarios/";
    all.push_back(load_scenario(dir + name));
  }
  for (const Scenario& s : all) {
    INFO(s.source);
    const nlohmann::json described = describe_scenario(s);
    const Scenario again = parse_scenario(described, s.source + " (described)", s.base_dir);
    // Describing is a fixed point, and nothing is left to fill in.
    CHECK(nlohmann::json(describe_scenario(again)) == described);
    CHECK(Fingerprint::to_hex(run_coverage(again).fingerprint) ==
          Fingerprint::to_hex(run_coverage(s).fingerprint));
  }
}
