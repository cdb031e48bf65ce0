#include "robot/coverage_config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace covsim {

double robot_spacing(const Environment& env, std::size_t n) {
  // No robots (a scenario read for its cells): the whole area is one robot's.
  return std::sqrt(env.area() / static_cast<double>(std::max<std::size_t>(n, 1)));
}

namespace {
// A choice's name in its table of (value, name) pairs, the value a name stands for, and
// every name: the one list of names each choice has.
template <class Table, class Value>
std::string_view name_in(const Table& table, Value v) {
  for (const auto& [value, name] : table) {
    if (value == v) return name;
  }
  return "unknown";
}

template <class Table>
auto value_named(const Table& table, std::string_view n)
    -> std::optional<typename Table::value_type::first_type> {
  for (const auto& [value, name] : table) {
    if (name == n) return value;
  }
  return std::nullopt;
}

template <class Table>
std::vector<std::string> names_in(const Table& table) {
  std::vector<std::string> out;
  for (const auto& [value, name] : table)
    out.emplace_back(name);
  return out;
}
}  // namespace

std::string_view to_string(ProjectionPolicy p) {
  return name_in(kProjectionPolicies, p);
}

std::optional<ProjectionPolicy> projection_named(std::string_view name) {
  return value_named(kProjectionPolicies, name);
}

std::string_view to_string(KnownEnvironment k) {
  return name_in(kKnownEnvironments, k);
}

std::optional<KnownEnvironment> known_environment_named(std::string_view name) {
  return value_named(kKnownEnvironments, name);
}

namespace {
using Key = ConfigKey<CoverageConfig>;

// A tolerance as the run uses it: given, or derived from Ω and the robots' spacing.
Key tolerance_key(const char* name, std::optional<double> CoverageConfig::*member,
                  const char* what) {
  return Key{ParamSpec::number(name, "m", what)
                 .positive()
                 .or_null()
                 .derived("1e-3 × diameter of Ω's box, or spacing_tolerance × spacing"),
             [member](CoverageConfig& c, const ParamValue& v) { config_value::from(v, c.*member); },
             [member](const CoverageConfig& c, const RunShape& s) -> std::optional<ParamValue> {
               const double diameter = s.environment.diameter();
               const double spacing = robot_spacing(s.environment, s.robots);
               return (c.*member).value_or(c.default_tolerance(diameter, spacing));
             }};
}
}  // namespace

ConfigKeys<CoverageConfig> motion_keys() {
  const CoverageConfig d;
  return {member_key<CoverageConfig>(
              ParamSpec::number("max_speed", "m/s",
                                "robots and virtual generators move at most this fast")
                  .positive()
                  .defaults_to(d.max_speed),
              &CoverageConfig::max_speed),
          member_key<CoverageConfig>(
              ParamSpec::number("radius", "m",
                                "robots are disks of this radius: they plan, sense and move in Ω "
                                "shrunk by it (corners mitered), their targets projected onto "
                                "it, while cells and costs stay on Ω; 0: points")
                  .non_negative()
                  .defaults_to(d.radius),
              &CoverageConfig::radius),
          member_key<CoverageConfig>(
              ParamSpec::number("inflation", "σ",
                                "a map planner beside a localization other than exact plans on "
                                "Ω shrunk by the radius plus this many standard deviations of "
                                "the position estimate's error, from the estimate (a costmap's "
                                "inflation)")
                  .non_negative()
                  .at_most(100.0)
                  .defaults_to(d.inflation),
              &CoverageConfig::inflation)};
}

ConfigKeys<CoverageConfig> projection_keys() {
  const CoverageConfig d;
  return {Key{ParamSpec::choice("projection", names_in(kProjectionPolicies),
                                "what the planner is told when a target lies outside Ω, whatever "
                                "the type: the paper's \"discover\" or \"known\" (below)")
                  .defaults_to(std::string(to_string(d.projection))),
              [](CoverageConfig& c, const ParamValue& v) {
                c.projection = *projection_named(std::get<std::string>(v));
              },
              [](const CoverageConfig& c, const RunShape&) -> std::optional<ParamValue> {
                return std::string(to_string(c.projection));
              }}};
}

ConfigKeys<CoverageConfig> environment_keys() {
  const CoverageConfig d;
  return {Key{ParamSpec::choice("known", names_in(kKnownEnvironments),
                                "what the robots know of Ω beforehand: \"full\" (the paper's), "
                                "\"boundary\" (the outer ring; holes are found by sensing) or "
                                "\"none\" (the bounding box; the outer ring's pockets and the "
                                "holes are found by sensing). See \"mapping\"")
                  .defaults_to(std::string(to_string(d.mapping.known))),
              [](CoverageConfig& c, const ParamValue& v) {
                c.mapping.known = *known_environment_named(std::get<std::string>(v));
              },
              [](const CoverageConfig& c, const RunShape&) -> std::optional<ParamValue> {
                return std::string(to_string(c.mapping.known));
              }}};
}

ConfigKeys<CoverageConfig> mapping_keys() {
  const CoverageConfig d;
  return {member_key<CoverageConfig>(
              ParamSpec::number("spacing", "m",
                                "a robot keeps a range reading for its map each time it has "
                                "travelled this far, and where it settles")
                  .positive()
                  .defaults_to(d.mapping.spacing),
              &CoverageConfig::mapping, &MappingConfig::spacing),
          member_key<CoverageConfig>(
              ParamSpec::number("max_bytes", "bytes",
                                "map bytes a broadcast carries at most: readings not yet sent "
                                "first, then older ones again in turn (decentralized runs)")
                  .at_least(64)
                  .at_most(65536)
                  .defaults_to(d.mapping.max_bytes),
              &CoverageConfig::mapping, &MappingConfig::max_bytes),
          member_key<CoverageConfig>(
              ParamSpec::number("cells", "cells",
                                "cells of the known-area lattice across Ω's bounding box (the "
                                "measured area is exact to a band one cell wide)")
                  .at_least(8)
                  .at_most(4096)
                  .defaults_to(d.mapping.cells),
              &CoverageConfig::mapping, &MappingConfig::cells),
          member_key<CoverageConfig>(
              ParamSpec::boolean("compare_known",
                                 "also run the scenario with Ω known from the same starts and "
                                 "seed, for mapping.cost_ratio")
                  .defaults_to(d.mapping.compare_known),
              &CoverageConfig::mapping, &MappingConfig::compare_known),
          member_key<CoverageConfig>(
              ParamSpec::boolean("robot_maps",
                                 "map.csv also holds when each robot's own map first held each "
                                 "cell (decentralized runs), for figures of one robot's map")
                  .defaults_to(d.mapping.robot_maps),
              &CoverageConfig::mapping, &MappingConfig::robot_maps),
          Key{ParamSpec::choice("model", {"auto", "polygons", "occupancy"},
                                "the map: \"polygons\" (the obstacles whose walls the readings "
                                "showed, exact), \"occupancy\" (a log-odds occupancy grid on the "
                                "lattice's cells, for uncertain readings) or \"auto\" (polygons "
                                "when readings are exact, else occupancy)")
                  .defaults_to(d.mapping.model),
              [](CoverageConfig& c, const ParamValue& v) {
                c.mapping.model = std::get<std::string>(v);
              },
              [](const CoverageConfig& c, const RunShape&) -> std::optional<ParamValue> {
                return c.mapping.model;
              }},
          member_key<CoverageConfig>(
              ParamSpec::number("p_hit", "",
                                "the occupancy grid's probability that a cell a reading's wall "
                                "meets is occupied (OctoMap's default)")
                  .greater_than(0.5)
                  .below(1.0)
                  .defaults_to(d.mapping.p_hit),
              &CoverageConfig::mapping, &MappingConfig::p_hit),
          member_key<CoverageConfig>(
              ParamSpec::number("p_miss", "",
                                "the occupancy grid's probability that a cell a reading shows "
                                "free is occupied (OctoMap's default)")
                  .greater_than(0.0)
                  .below(0.5)
                  .defaults_to(d.mapping.p_miss),
              &CoverageConfig::mapping, &MappingConfig::p_miss)};
}

ConfigKeys<CoverageConfig> sensor_keys() {
  const CoverageConfig d;
  return {
      // The config's infinite range is null in the file.
      Key{ParamSpec::number("range", "m",
                            "sensing range: 0 (contact sensing), a finite range, or null for "
                            "infinite")
              .non_negative()
              .or_null()
              .defaults_to(std::monostate{}),
          [](CoverageConfig& c, const ParamValue& v) {
            c.sensor.range = std::holds_alternative<double>(v) ? std::get<double>(v) : INFINITY;
          },
          [](const CoverageConfig& c, const RunShape&) -> std::optional<ParamValue> {
            if (std::isinf(c.sensor.range)) return ParamValue(std::monostate{});
            return c.sensor.range;
          }},
      member_key<CoverageConfig>(
          period_param("period",
                       "seconds between range readings; null: a fresh reading at every loop-2 "
                       "step. Between readings the planner works with the latest one")
              .or_null()
              .defaults_to(config_value::to(d.sensor.period)),
          &CoverageConfig::sensor, &SensorConfig::period),
      // Required in "noise": {"sigma": s}; a file without "noise" has none.
      member_key<CoverageConfig>(
          ParamSpec::number("noise.sigma", "m",
                            "Gaussian range noise: every sensed point moves along its ray from "
                            "the robot by N(0, sigma²); no noise without \"noise\"")
              .non_negative(),
          &CoverageConfig::sensor, &SensorConfig::noise_sigma),
      member_key<CoverageConfig>(
          ParamSpec::number("dropout", "",
                            "probability that a reading is lost (the planner keeps the previous "
                            "one; the first is never lost)")
              .probability()
              .defaults_to(d.sensor.dropout),
          &CoverageConfig::sensor, &SensorConfig::dropout)};
}

ConfigKeys<CoverageConfig> loop_keys() {
  const CoverageConfig d;
  const auto mode_name = [](LoopMode m) {
    return std::string(m == LoopMode::periodic ? "periodic" : "classic");
  };
  return {
      Key{ParamSpec::choice("mode", {"classic", "periodic"},
                            "\"classic\": a robot runs loop 1 again once it has reached its real "
                            "target or settled at its projection, as in the paper; "
                            "\"periodic\": loop 1 every loop1_period")
              .defaults_to(mode_name(d.mode)),
          [](CoverageConfig& c, const ParamValue& v) {
            c.mode =
                std::get<std::string>(v) == "periodic" ? LoopMode::periodic : LoopMode::classic;
          },
          [mode_name](const CoverageConfig& c, const RunShape&) -> std::optional<ParamValue> {
            return mode_name(c.mode);
          }},
      member_key<CoverageConfig>(
          period_param("loop2_period",
                       "seconds between motion steps (each at most max_speed × loop2_period long)")
              .defaults_to(d.loop2_period.seconds()),
          &CoverageConfig::loop2_period),
      // After "mode" and "loop2_period", which it depends on, and before "loop1_period",
      // which it excludes. Written back as loop1_period.
      Key{ParamSpec::number("ratio", "",
                            "the Lloyd/planner frequency ratio, \"periodic\" only: loop 1 every "
                            "ratio motion steps (loop1_period = ratio × loop2_period; give one of "
                            "the two); null: not set, as in a sweep's zip beside \"classic\"")
              .positive()
              .or_null()
              .derived("unset"),
          [](CoverageConfig& c, const ParamValue& v) {
            if (std::holds_alternative<std::monostate>(v)) return;
            const double ratio = std::get<double>(v);
            if (c.mode != LoopMode::periodic)
              throw ParamError("ratio", "ratio applies to \"mode\": \"periodic\" only");
            const double period = ratio * c.loop2_period.seconds();
            if (!(period >= kMinPeriod && period <= kMaxPeriod))
              throw ParamError("ratio", fmt::format("ratio × loop2_period is {} s, outside the "
                                                    "periods a run resolves ({} s to {} s)",
                                                    period, kMinPeriod, kMaxPeriod));
            c.loop1_period = SimTime::from_seconds(period);
            c.loop_ratio = ratio;
          },
          [](const CoverageConfig&, const RunShape&) -> std::optional<ParamValue> {
            return std::nullopt;
          }},
      Key{period_param("loop1_period",
                       "seconds between Lloyd updates, \"periodic\" only (an error otherwise); "
                       "loop1_period / loop2_period is the Lloyd/planner frequency ratio; null: "
                       "not set")
              .or_null()
              .defaults_to(d.loop1_period.seconds()),
          [](CoverageConfig& c, const ParamValue& v) {
            if (std::holds_alternative<std::monostate>(v)) return;
            if (c.mode != LoopMode::periodic)
              throw ParamError("loop1_period",
                               "loop1_period applies to \"mode\": \"periodic\" only");
            if (c.loop_ratio)
              throw ParamError("loop1_period", "give loop1_period or ratio, not both");
            config_value::from(v, c.loop1_period);
          },
          [](const CoverageConfig& c, const RunShape&) -> std::optional<ParamValue> {
            if (c.mode != LoopMode::periodic) return std::nullopt;
            return c.loop1_period.seconds();
          }}};
}

ConfigKeys<CoverageConfig> convergence_keys() {
  const CoverageConfig d;
  return {tolerance_key("position_tolerance", &CoverageConfig::position_tolerance,
                        "a robot within this distance of its real target is settled; null: the "
                        "default"),
          tolerance_key("virtual_tolerance", &CoverageConfig::virtual_tolerance,
                        "a virtual generator within this distance of its virtual target is at "
                        "rest; null: the default"),
          // Written back as the two tolerances it sets.
          Key{ParamSpec::number("spacing_tolerance", "",
                                "both tolerances default to this fraction of the robots' spacing "
                                "√(area of Ω / N) instead; a tolerance given explicitly wins")
                  .greater_than(0)
                  .at_most(1)
                  .worded("a fraction of the robots' spacing")
                  .derived("unset"),
              [](CoverageConfig& c, const ParamValue& v) {
                config_value::from(v, c.spacing_tolerance);
              },
              [](const CoverageConfig&, const RunShape&) -> std::optional<ParamValue> {
                return std::nullopt;
              }},
          member_key<CoverageConfig>(
              period_param("max_time", "simulated seconds after which a run stops unconverged")
                  .defaults_to(d.max_time.seconds()),
              &CoverageConfig::max_time)};
}

ConfigKeys<CoverageConfig> metrics_keys() {
  const CoverageConfig d;
  return {member_key<CoverageConfig>(
              period_param("period", "simulated seconds between rows of metrics.csv")
                  .defaults_to(d.sample_period.seconds()),
              &CoverageConfig::sample_period),
          member_key<CoverageConfig>(
              ParamSpec::integer("algebraic_connectivity_robots", "robots",
                                 "the most robots for which a networked run's metrics.csv gets "
                                 "the communication graph's algebraic_connectivity (below)")
                  .defaults_to(d.algebraic_connectivity_robots),
              &CoverageConfig::algebraic_connectivity_robots)};
}

ConfigKeys<NetworkConfig> network_keys() {
  using NetKey = ConfigKey<NetworkConfig>;
  const NetworkConfig d;
  return {
      member_key<NetworkConfig>(
          ParamSpec::number("range", "m",
                            "a message reaches only robots within range (null: unlimited)")
              .positive()
              .or_null()
              .defaults_to(config_value::to(d.channel.range)),
          &NetworkConfig::channel, &ChannelConfig::range),
      member_key<NetworkConfig>(
          ParamSpec::boolean("line_of_sight",
                             "walls block: the straight line between the robots must lie in Ω")
              .defaults_to(d.channel.line_of_sight),
          &NetworkConfig::channel, &ChannelConfig::line_of_sight),
      member_key<NetworkConfig>(
          period_param("broadcast_period", "seconds between a robot's broadcasts")
              .defaults_to(d.broadcast_period.seconds()),
          &NetworkConfig::broadcast_period),
      NetKey{ParamSpec::boolean("random_phase",
                                "each robot's first broadcast at a random offset within the period")
                 .derived("false; true with a simulated radio (network.channel), on which "
                          "broadcasts at one instant would all collide"),
             [](NetworkConfig& n, const ParamValue& v) { config_value::from(v, n.random_phase); },
             [](const NetworkConfig& n, const RunShape&) -> std::optional<ParamValue> {
               return n.phases_random();
             }},
      member_key<NetworkConfig>(
          period_param("staleness",
                       "seconds after which an entry is dropped (by its send time); null: never")
              .or_null()
              .defaults_to(config_value::to(d.staleness)),
          &NetworkConfig::staleness),
      NetKey{duration_param("acquire",
                            "seconds from the start to a robot's first loop 1, while it hears "
                            "its neighbours (Algorithm 1, line 3)")
                 .derived("one broadcast period"),
             [](NetworkConfig& n, const ParamValue& v) { config_value::from(v, n.acquire); },
             [](const NetworkConfig& n, const RunShape&) -> std::optional<ParamValue> {
               return n.acquire_time().seconds();
             }},
      NetKey{
          duration_param("acquire_timeout",
                         "seconds from the start after which a robot that has heard nobody "
                         "runs loop 1 alone (its cell is Ω); until then it waits for its "
                         "first message")
              .derived("ten broadcast periods"),
          [](NetworkConfig& n, const ParamValue& v) { config_value::from(v, n.acquire_timeout); },
          [](const NetworkConfig& n, const RunShape&) -> std::optional<ParamValue> {
            return n.acquire_deadline().seconds();
          }}};
}

bool readings_uncertain(const CoverageConfig& c) {
  return c.localization.type != LocalizationConfig{}.type || c.sensor.noise_sigma > 0.0;
}

bool maps_on_grid(const CoverageConfig& c) {
  return c.mapping.model == "occupancy" || (c.mapping.model == "auto" && readings_uncertain(c));
}

}  // namespace covsim
