#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/random_stream.hpp"
#include "geometry/cell_integrator.hpp"
#include "geometry/configuration_space.hpp"
#include "geometry/geometry_error.hpp"
#include "geometry/placement.hpp"
#include "geometry/ring_validation.hpp"
#include "net/message.hpp"
#include "planners/planner_map.hpp"
#include "robot/localization_registry.hpp"
#include "scenarios/component_reader.hpp"
#include "scenarios/component_sections.hpp"
#include "scenarios/input_file.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/section_reader.hpp"

namespace covsim {

namespace {

// The limits docs/scenario-format.md states: what a double resolves and a run can afford
// (the periods' are in core/config_key.hpp).
constexpr double kMaxCoordinate = 1e6;     // m
constexpr double kMinExtent = 1e-3;        // m: Ω's box diagonal
constexpr double kMinRelativeEdge = 1e-6;  // an edge against Ω's box diagonal

std::shared_ptr<const Environment> read_environment(const JsonValue& v) {
  v.only_keys({"outer", "holes", "known"});
  std::vector<Vec2> outer = v.at("outer").points();
  std::vector<std::vector<Vec2>> holes;
  if (auto h = v.find("holes")) {
    for (std::size_t i = 0; i < h->size(); ++i)
      holes.push_back((*h)[i].points());
  }
  // Sizes a double resolves: coordinates within ±1e6 m, Ω at least 1 mm across, no edge
  // shorter than a millionth of Ω (a finer feature would be lost in the tolerances).
  const auto ring_value = [&](std::size_t r) {
    return r == 0 ? v.at("outer") : v.at("holes")[r - 1];
  };
  Box box;
  for (std::size_t r = 0; r <= holes.size(); ++r) {
    const std::vector<Vec2>& ring = r == 0 ? outer : holes[r - 1];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (std::abs(ring[i].x) > kMaxCoordinate || std::abs(ring[i].y) > kMaxCoordinate)
        ring_value(r)[i].fail(
            fmt::format("coordinates beyond ±{:g} m are not supported (found ({}, {}))",
                        kMaxCoordinate, ring[i].x, ring[i].y));
      if (r == 0) box.add(ring[i]);
    }
  }
  const double extent = norm(box.size());
  if (!(extent >= kMinExtent))
    v.at("outer").fail(fmt::format("the environment is {:g} m across; at least {:g} m is supported",
                                   extent, kMinExtent));
  for (std::size_t r = 0; r <= holes.size(); ++r) {
    const std::vector<Vec2>& ring = r == 0 ? outer : holes[r - 1];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const double edge = distance(ring[i], ring[(i + 1) % ring.size()]);
      if (edge > 0 && edge < kMinRelativeEdge * extent)
        ring_value(r)[i].fail(fmt::format(
            "the edge from this vertex is {:g} m long, below {:g} of the environment's size "
            "({:g} m): too small to resolve",
            edge, kMinRelativeEdge, extent));
    }
  }
  try {
    return std::make_shared<const Environment>(std::move(outer), std::move(holes));
  } catch (const GeometryError& e) {
    const std::string at = e.ring() < 0    ? v.path()
                           : e.ring() == 0 ? v.path() + ".outer"
                                           : fmt::format("{}.holes[{}]", v.path(), e.ring() - 1);
    throw ScenarioError(v.file(), at, e.what());
  }
}

std::shared_ptr<const Density> read_density(const JsonValue& v,
                                            const std::filesystem::path& base_dir,
                                            const Environment& env,
                                            std::optional<std::uint64_t> seed) {
  const auto& row = component_section<DensityEntry>();
  const ComponentChoice c = read_component(v, row);
  std::shared_ptr<const Density> d;
  try {
    d = row.registry().at(c.type).make(DensityContext{env, base_dir, seed}, c.params);
  } catch (const ParamError& e) {
    fail_param(v, e);
  } catch (const std::invalid_argument& e) {
    v.fail(e.what());
  }
  if (!(CellIntegrator(env, *d).total_mass() > 0.0))
    v.fail("the density has no mass on the environment");
  return d;
}

// The object a network section's component makes from its parameters (a loss, delay or
// channel model), and the type chosen.
template <class Entry>
auto make_network_component(const JsonValue& section, std::string& type) {
  const auto& row = component_section<Entry>();
  const ComponentChoice choice = read_component(section, row);
  type = choice.type;
  try {
    return row.registry().at(choice.type).make(choice.params);
  } catch (const ParamError& e) {
    fail_param(section, e);
  }
}

// The components a coverage run selects, each from its section of the table.
void read_components(const JsonValue& root, CoverageConfig& c) {
  // null: the ideal network, as if absent (so that a sweep can vary it against others).
  if (auto n = root.find("network"); n && !n->is_null()) {
    std::string type;
    if (auto loss = n->find("loss"))
      c.network.channel.loss = make_network_component<LossEntry>(*loss, type);
    if (auto delay = n->find("delay"))
      c.network.channel.delay = make_network_component<DelayEntry>(*delay, type);
    if (auto channel = n->find("channel")) {
      c.network.channel.model = make_network_component<ChannelEntry>(*channel, type);
      // A simulated radio decides reach, loss and delay itself: the abstract channel's keys
      // beside it would be silently ignored.
      if (const auto& model = c.network.channel.model) {
        for (const std::string& key : model->replaces()) {
          // null, or false for line_of_sight, states the abstract channel's default: allowed.
          if (auto v = n->find(key); v && !v->is_null() && v->raw() != false)
            v->fail(fmt::format("does not apply to the {} channel, which decides it itself", type));
        }
      }
    }
  }
  if (auto p = root.find("planner")) {
    const ComponentChoice choice = read_component(*p, component_section<PlannerEntry>());
    c.planner = PlannerConfig{choice.type, choice.params};
  }
  if (auto r = root.find("robots")) {
    if (auto a = r->find("avoidance")) {
      const ComponentChoice choice = read_component(*a, component_section<AvoidanceEntry>());
      c.avoidance = AvoidanceConfig{choice.type, choice.params};
      if (c.radius == 0.0 && c.avoidance.type != AvoidanceConfig{}.type)
        a->fail(fmt::format(
            "{} avoids bodies, and robots.radius is 0 (points): give the robots a radius",
            c.avoidance.type));
    }
    if (auto kin = r->find("kinematics")) {
      const ComponentChoice choice = read_component(*kin, component_section<KinematicsEntry>());
      c.kinematics = KinematicsConfig{choice.type, choice.params};
    }
    if (auto loc = r->find("localization")) {
      const ComponentChoice choice = read_component(*loc, component_section<LocalizationEntry>());
      c.localization = LocalizationConfig{choice.type, choice.params};
      // A planner on Ω's map plans from the estimate, on Ω inflated by the estimate's
      // error, which must stay bounded. A planner on a sensed map plans in its odometry's
      // frame, where the walls it senses stay put only if the odometry does not drift.
      const PlannerEntry* planner = planner_registry().find(c.planner.type);
      const LocalizationEntry& located = localization_registry().at(c.localization.type);
      if (c.localization.type != LocalizationConfig{}.type && planner != nullptr &&
          !planner->senses_only) {
        const bool sensed = plans_on_sensed_map(c.planner.params) ||
                            (c.mapping.unknown() && !c.planner.params.has(kPlannerMapKey));
        const ParamSpec* drift = find_param(located.params, "drift");
        const double drifts = drift == nullptr ? 0.0
                              : c.localization.params.has("drift")
                                  ? c.localization.params.number("drift")
                                  : std::get<double>(*drift->default_value);
        if (sensed && drifts > 0.0)
          loc->fail(fmt::format(
              "{} localization with drift {} beside a planner on a sensed map: the walls it "
              "maps move with its drifting odometry, and keeping them in place needs loop "
              "closure (SLAM), which is not modelled; use drift 0 (tracking's default), "
              "tangent_bug, or planner.map \"given\"",
              c.localization.type, drifts));
        if (!sensed && !located.bounded)
          loc->fail(fmt::format(
              "{} localization beside the map planner {}: its error grows without bound, so "
              "no inflation of the map covers it; use tracking (fixes) or tangent_bug",
              c.localization.type, c.planner.type));
      }
    }
  }
  if (auto k = root.find("controller")) {
    // The section's own keys (the projection policy) are read with the fixed sections.
    std::vector<std::string> own;
    for (const ParamSpec& spec : scenario_section("controller").schema())
      own.push_back(spec.name);
    const ComponentChoice choice = read_component(*k, component_section<LawEntry>(), own);
    c.law = LawConfig{choice.type, choice.params};
  }
}

// The fixed sections, through their keys (scenario_sections.hpp). A section that shares its
// object with components leaves their keys to them: the controller's type and parameters,
// the network's loss and delay.
void read_fixed_sections(const JsonValue& root, Scenario& s) {
  for (const ScenarioSection& section : scenario_sections()) {
    const auto v = root.find(section.path);
    if (!v || (section.null_is_absent && v->is_null())) continue;
    bool shared = false;
    std::vector<std::string> other = section.other_keys;
    for_each_component_section([&](const auto& row) {
      if (row.path == section.path) shared = true;
      if (row.path.rfind(section.path + ".", 0) == 0)
        other.push_back(row.path.substr(section.path.size() + 1));
    });
    if (!shared) check_section_keys(*v, section, other);
    read_section(*v, section, s);
  }
}

void check_distinct(const JsonValue& list, const std::vector<Vec2>& positions,
                    const ConfigurationSpace& space) {
  const Environment& env = space.environment();
  const double r = space.radius();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec2 p = positions[i];
    if (!env.contains(p))
      list[i].fail(
          fmt::format("robot at ({}, {}) is not in the environment (outside it or "
                      "inside an obstacle)",
                      p.x, p.y));
    if (r > 0.0 && !space.part_of(p))
      list[i].fail(fmt::format(
          "robot at ({}, {}) is {:.6g} m from a wall: its body (robots.radius {} m) overlaps it",
          p.x, p.y, env.boundary_distance(p), r));
    for (std::size_t j = 0; j < i; ++j) {
      if (positions[j] == p)
        list[i].fail(fmt::format("robots {} and {} start at the same position", j, i));
      if (r > 0.0 && distance(positions[j], p) < 2.0 * r - env.tolerance())
        list[i].fail(fmt::format(
            "robots {} and {} start {:.6g} m apart: their bodies (robots.radius {} m) overlap", j,
            i, distance(positions[j], p), r));
    }
  }
}

Placement read_start(const JsonValue& v) {
  v.only_keys({"uniform", "region", "cluster"});
  const int given =
      (v.find("uniform") ? 1 : 0) + (v.find("region") ? 1 : 0) + (v.find("cluster") ? 1 : 0);
  if (given != 1) v.fail("expected exactly one of \"uniform\", \"region\" and \"cluster\"");
  Placement p;
  if (auto u = v.find("uniform")) {
    if (!u->boolean()) u->fail("expected true (or another kind of start)");
    p.kind = Placement::Kind::uniform;
  } else if (auto r = v.find("region")) {
    p.kind = Placement::Kind::region;
    try {
      p.region = normalize_ring(r->points(), 0, true);
    } catch (const GeometryError& e) {
      r->fail(fmt::format("expected a simple polygon: {}", e.what()));
    }
  } else {
    const JsonValue c = v.at("cluster");
    c.only_keys({"center", "radius"});
    p.kind = Placement::Kind::cluster;
    p.center = c.at("center").point();
    p.radius = c.at("radius").positive();
  }
  return p;
}

// The area robots are drawn over, for the default separation.
double start_area(const Placement& p, const Environment& env) {
  switch (p.kind) {
    case Placement::Kind::uniform:
      return env.area();
    case Placement::Kind::region:
      return std::fabs(signed_area(p.region));
    case Placement::Kind::cluster:
      return std::numbers::pi * p.radius * p.radius;
  }
  return env.area();
}

// "robots": given positions (perturbed by "jitter" per seed), or "count" robots drawn per seed
// by "start". Draws come from the seed's "robot-start" stream.
std::vector<Vec2> read_robots(const JsonValue& v, const Environment& env, double radius,
                              std::optional<std::uint64_t> seed, const RobotDraw& draw) {
  std::optional<ConfigurationSpace> space;
  try {
    space.emplace(env, radius);
  } catch (const GeometryError& e) {
    v.fail(e.what());
  }
  const auto positions = v.find("positions");
  const auto count = v.find("count");
  if (positions && count) v.fail("expected \"positions\" or \"count\", not both");
  if (!positions && !count)
    v.fail("missing required key \"positions\" (or \"count\" and \"start\")");
  const auto stream = [&](const JsonValue& where) {
    if (!seed)
      where.fail("robots drawn per seed need the scenario's \"seed\" (or covsim run --seed)");
    return RandomStream(*seed, 0, "robot-start");
  };
  std::vector<Vec2> out;
  if (positions) {
    if (auto s = v.find("start")) s->fail("\"start\" goes with \"count\", not \"positions\"");
    out = positions->points();
    if (out.empty()) positions->fail("expected at least one robot");
    check_distinct(*positions, out, *space);
    if (auto j = v.find("jitter")) {
      const double sigma = draw.jitter;
      if (auto s = v.find("separation")) s->fail("\"separation\" goes with \"count\"");
      if (sigma > 0.0) {
        // Each robot moves by a Gaussian step per coordinate, redrawn until it lands in Ω
        // and on no other robot.
        RandomStream rng = stream(*j);
        for (std::size_t i = 0; i < out.size(); ++i) {
          const Vec2 given = out[i];
          for (int tries = 0;; ++tries) {
            if (tries == 1000)
              (*positions)[i].fail(fmt::format(
                  "no jittered position in Ω found in 1000 tries (jitter {} m)", sigma));
            const Vec2 q = given + Vec2{rng.normal(0.0, sigma), rng.normal(0.0, sigma)};
            bool free = radius > 0.0 ? space->part_of(q).has_value() : env.contains(q);
            for (std::size_t k = 0; free && k < out.size(); ++k)
              free = k == i || (!(out[k] == q) && distance(out[k], q) >= 2.0 * radius);
            if (free) {
              out[i] = q;
              break;
            }
          }
        }
      }
    } else if (auto s = v.find("separation")) {
      s->fail("\"separation\" goes with \"count\"");
    }
    return out;
  }
  if (auto j = v.find("jitter")) j->fail("\"jitter\" goes with \"positions\"");
  const std::uint64_t n = count->unsigned_integer();
  if (n == 0 || n > 100000) count->fail(fmt::format("expected 1 to 100000 robots, found {}", n));
  const JsonValue start = v.at("start");
  const Placement placement = read_start(start);
  // Bodies may touch but not overlap.
  const double separation =
      std::max(2.0 * radius, draw.separation.value_or(0.05 * std::sqrt(start_area(placement, env) /
                                                                       static_cast<double>(n))));
  RandomStream rng = stream(start);
  const auto body_fits = [&](Vec2 q) { return space->part_of(q).has_value(); };
  try {
    out = place_points(env, placement, n, separation, rng, {},
                       radius > 0.0 ? std::function<bool(Vec2)>(body_fits) : nullptr);
  } catch (const PlacementError& e) {
    start.fail(e.what());
  }
  return out;
}

// The run's size before it starts: motion steps per robot and trajectory rows, each against
// its limit (raised in "limits"); the error points at max_time, what makes a run long.
void check_limits(const JsonValue& root, const Scenario& s) {
  const CoverageConfig& c = s.coverage;
  const auto at = root.find("convergence") && root.at("convergence").find("max_time")
                      ? *root.at("convergence").find("max_time")
                      : root;
  const double steps = c.max_time.seconds() / c.loop2_period.seconds();
  if (steps > s.limits.motion_steps) {
    at.fail(fmt::format(
        "max_time {:g} s at a loop-2 period of {:g} s is {:g} motion steps per robot, more than "
        "limits.motion_steps ({:g}); lower max_time, raise loops.loop2_period, or raise the limit",
        c.max_time.seconds(), c.loop2_period.seconds(), steps, s.limits.motion_steps));
  }
  const double period = std::max(c.loop2_period.seconds(), s.recording.trajectory_period);
  const double rows =
      static_cast<double>(s.robot_positions.size()) * (c.max_time.seconds() / period + 2.0);
  if (rows > s.limits.trajectory_rows) {
    at.fail(fmt::format(
        "{} robots until max_time {:g} s write up to {:.3g} rows of trajectory.csv (about {:.0f} "
        "MB), more than limits.trajectory_rows ({:g}); lower max_time, thin the file with "
        "recording.trajectory_period, or raise the limit",
        s.robot_positions.size(), c.max_time.seconds(), rows, rows * 150e-6,
        s.limits.trajectory_rows));
  }
}

// Robots that do not know Ω (environment.known) map it from what they sense: every part
// that would be told Ω, or needs a map from exact readings, is refused beside it.
void check_mapping(const JsonValue& root, CoverageConfig& c) {
  if (!c.mapping.unknown()) {
    // Its defaults may be stated (a described scenario states them); others would be ignored.
    if (auto m = root.find("mapping"); m && !(c.mapping == MappingConfig{}))
      m->fail(
          "applies only to robots that do not know Ω: set environment.known to "
          "\"boundary\" or \"none\"");
    return;
  }
  const JsonValue known = root.at("environment").at("known");
  const PlannerEntry* planner = planner_registry().find(c.planner.type);
  if (planner != nullptr && !planner->senses_only && !planner->blind) {
    // A map planner plans on what its robot sensed: implied, and the given map refused.
    if (find_param(planner->params, kPlannerMapKey) == nullptr)
      known.fail(
          fmt::format("robots that do not know Ω need a planner that plans from what it senses "
                      "(tangent_bug, or a map planner with planner.map \"sensed\"); {} "
                      "plans on a map of Ω",
                      c.planner.type));
    if (c.planner.params.has(kPlannerMapKey) && !plans_on_sensed_map(c.planner.params))
      root.at("planner")
          .at(std::string(kPlannerMapKey))
          .fail(
              "robots that do not know Ω cannot plan on the given map: use \"sensed\" (the "
              "default when environment.known is \"boundary\" or \"none\")");
    c.planner.params.set(std::string(kPlannerMapKey), std::string("sensed"));
  }
  if (c.projection == ProjectionPolicy::known)
    known.fail(
        "controller.projection \"known\" projects targets onto Ω, which the robots do "
        "not know: use \"discover\" (the default)");
  if (const LawEntry* law = coverage_law_registry().find(c.law.type); law && law->needs_map)
    known.fail(
        fmt::format("the {} law needs Ω's geodesic distances, which robots that do not "
                    "know Ω cannot compute",
                    c.law.type));
  // The polygon map names the walls a reading saw, which an uncertain reading cannot tell.
  if (c.mapping.model == "polygons" && readings_uncertain(c))
    root.at("mapping").at("model").fail(
        "the polygon map takes the walls each reading saw as exact, which readings with range "
        "noise or placed by an uncertain position are not: use \"occupancy\" or \"auto\"");
  if (c.network.channel.model && kStateMessageBytes + c.mapping.max_bytes > kMaxRadioMessageBytes)
    root.at("mapping")
        .at("max_bytes")
        .fail(fmt::format(
            "a simulated radio carries messages of at most {} bytes, {} of them the state: at most "
            "{} map bytes",
            kMaxRadioMessageBytes, kStateMessageBytes, kMaxRadioMessageBytes - kStateMessageBytes));
}

// The keys a scenario file may have at its top: the environment, the seed, and the sections.
std::vector<std::string> top_level_keys() {
  std::vector<std::string> keys{"environment", "seed"};
  const auto add = [&](const std::string& path) {
    const std::string top = path.substr(0, path.find('.'));
    if (std::find(keys.begin(), keys.end(), top) == keys.end()) keys.push_back(top);
  };
  for_each_component_section([&](const auto& row) { add(row.path); });
  for (const ScenarioSection& section : scenario_sections())
    add(section.path);
  return keys;
}

}  // namespace

Scenario parse_scenario(const nlohmann::json& json, const std::string& source,
                        const std::filesystem::path& base_dir) {
  Scenario s;
  s.source = source;
  s.json = json;
  const JsonValue root(s.json, source);
  root.only_keys(top_level_keys());
  if (auto seed = root.find("seed")) s.seed = seed->unsigned_integer();
  s.base_dir = base_dir;
  s.environment = read_environment(root.at("environment"));
  s.density = read_density(root.at("density"), base_dir, *s.environment, s.seed);
  read_fixed_sections(root, s);
  if (auto r = root.find("robots"))
    s.robot_positions = read_robots(*r, *s.environment, s.coverage.radius, s.seed, s.draw);
  read_components(root, s.coverage);
  check_mapping(root, s.coverage);
  check_limits(root, s);
  // Checks that need the environment (grids too fine for it) fail here, not at a run's start.
  const auto check = [&](const auto& entry, const Params& params, const char* key) {
    if (!entry.check) return;
    try {
      entry.check(*s.environment, params);
    } catch (const ParamError& e) {
      fail_param(root.at(key), e);
    }
  };
  if (root.find("planner"))
    check(component_section<PlannerEntry>().registry().at(s.coverage.planner.type),
          s.coverage.planner.params, "planner");
  if (root.find("controller"))
    check(component_section<LawEntry>().registry().at(s.coverage.law.type), s.coverage.law.params,
          "controller");
  return s;
}

Scenario load_scenario(const std::filesystem::path& file) {
  const InputFile in = read_input(file);
  try {
    return parse_scenario(in.json, in.source, file.parent_path());
  } catch (const ScenarioError& e) {
    throw in.located(e);
  }
}

bool draws_from_seed(const nlohmann::json& j) {
  if (j.contains("robots") && j["robots"].is_object()) {
    const auto& r = j["robots"];
    if (r.contains("count")) return true;
    if (r.contains("jitter") && r["jitter"].is_number() && r["jitter"].get<double>() > 0.0)
      return true;
  }
  if (j.contains("density") && j["density"].is_object() && j["density"].contains("components") &&
      j["density"]["components"].is_array()) {
    for (const auto& c : j["density"]["components"]) {
      if (c.is_object() && c.contains("mean") && c["mean"].is_null()) return true;
    }
  }
  return false;
}

Scenario with_seed(const Scenario& scenario, std::uint64_t seed) {
  if (scenario.seed == seed) return scenario;
  if (!draws_from_seed(scenario.json)) {
    Scenario s = scenario;
    s.seed = seed;
    s.json["seed"] = seed;
    return s;
  }
  nlohmann::json j = scenario.json;
  j["seed"] = seed;
  return parse_scenario(j, scenario.source, scenario.base_dir);
}

}  // namespace covsim
