#include "scenarios/scenario_description.hpp"

#include <cmath>
#include <optional>
#include <utility>

#include "geometry/density_registry.hpp"
#include "net/delay_registry.hpp"
#include "net/loss_registry.hpp"
#include "planners/planner_registry.hpp"
#include "robot/coverage_law_registry.hpp"
#include "scenarios/component_reader.hpp"

namespace covsim {

namespace {

nlohmann::ordered_json points(const std::vector<Vec2>& ps) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (Vec2 p : ps)
    a.push_back({p.x, p.y});
  return a;
}

nlohmann::ordered_json seconds(SimTime t) {
  return t.seconds();
}

// {type_key: type, every parameter}: constant and derived defaults filled in.
template <class Entry>
nlohmann::ordered_json component(const Registry<Entry>& registry, const std::string& type_key,
                                 const std::string& type, const Params& params,
                                 const Environment& env) {
  const Entry& e = registry.at(type);
  nlohmann::ordered_json j{{type_key, type}};
  const nlohmann::ordered_json values =
      params_to_json(with_derived(e.params, with_defaults(e.params, params), env));
  for (const auto& [k, v] : values.items())
    j[k] = v;
  return j;
}

// A component section as the file has it, read through its registry again.
template <class Entry>
nlohmann::ordered_json reread(const Scenario& s, const nlohmann::json& section,
                              const std::string& path, const Registry<Entry>& registry,
                              const std::string& type_key) {
  const ComponentChoice c = read_component(JsonValue(section, s.source, path), registry, type_key);
  return component(registry, type_key, c.type, c.params, *s.environment);
}

}  // namespace

nlohmann::ordered_json describe_scenario(const Scenario& s) {
  const Environment& env = *s.environment;
  const CoverageConfig& c = s.coverage;
  nlohmann::ordered_json out;
  nlohmann::ordered_json holes = nlohmann::ordered_json::array();
  for (std::size_t h = 0; h < env.hole_count(); ++h)
    holes.push_back(points(env.hole(h)));
  out["environment"] = {{"outer", points(env.outer())}, {"holes", holes}};
  out["density"] = reread(s, s.json.at("density"), "$.density", density_registry(), "type");
  if (!s.robot_positions.empty())
    out["robots"] = {{"positions", points(s.robot_positions)}, {"max_speed", c.max_speed}};
  if (s.seed) out["seed"] = *s.seed;
  out["planner"] = component(planner_registry(), "type", c.planner.type, c.planner.params, env);
  out["controller"] = component(coverage_law_registry(), "type", c.law.type, c.law.params, env);
  out["controller"]["projection"] = to_string(c.projection);
  out["sensor"] = {{"range", std::isinf(c.sensor.range) ? nlohmann::ordered_json(nullptr)
                                                        : nlohmann::ordered_json(c.sensor.range)},
                   {"period", c.sensor.period ? seconds(*c.sensor.period) : nullptr},
                   {"noise", {{"sigma", c.sensor.noise_sigma}}},
                   {"dropout", c.sensor.dropout}};
  nlohmann::ordered_json loops{{"mode", c.mode == LoopMode::periodic ? "periodic" : "classic"},
                               {"loop2_period", seconds(c.loop2_period)}};
  if (c.mode == LoopMode::periodic) loops["loop1_period"] = seconds(c.loop1_period);
  out["loops"] = loops;
  const double spacing = robot_spacing(env, s.robot_positions.size());
  out["convergence"] = {{"position_tolerance", c.position_tolerance_in(env.diameter(), spacing)},
                        {"virtual_tolerance", c.virtual_tolerance_in(env.diameter(), spacing)},
                        {"max_time", seconds(c.max_time)}};
  out["metrics"] = {{"period", seconds(c.sample_period)},
                    {"algebraic_connectivity_robots", c.algebraic_connectivity_robots}};
  out["recording"] = {{"trajectory_period", s.recording.trajectory_period},
                      {"compress", s.recording.compress}};
  out["limits"] = {{"motion_steps", s.limits.motion_steps},
                   {"trajectory_rows", s.limits.trajectory_rows}};
  // Only a scenario with a network has one: without, robots know each other's state at once.
  if (s.json.contains("network") && !s.json.at("network").is_null()) {
    const NetworkConfig& n = c.network;
    const nlohmann::json& section = s.json.at("network");
    nlohmann::ordered_json net{
        {"range", n.channel.range ? nlohmann::ordered_json(*n.channel.range) : nullptr},
        {"line_of_sight", n.channel.line_of_sight},
        {"broadcast_period", seconds(n.broadcast_period)},
        {"random_phase", n.random_phase},
        {"staleness", n.staleness ? seconds(*n.staleness) : nullptr},
        {"acquire", seconds(n.acquire_time())},
        {"acquire_timeout", seconds(n.acquire_deadline())}};
    net["loss"] = section.contains("loss")
                      ? reread(s, section.at("loss"), "$.network.loss", loss_registry(), "model")
                      : component(loss_registry(), "model", "none", {}, env);
    net["delay"] =
        section.contains("delay")
            ? reread(s, section.at("delay"), "$.network.delay", delay_registry(), "model")
            : nlohmann::ordered_json{{"model", "constant"}, {"value", 0.0}};
    out["network"] = net;
  }
  return out;
}

std::string scenario_key_unit(std::string_view path) {
  // The sections the loader reads itself (scenario_loader.cpp).
  static const std::pair<std::string_view, std::string_view> kFixed[] = {
      {"robots.max_speed", "m/s"},
      {"robots.separation", "m"},
      {"robots.jitter", "m"},
      {"sensor.range", "m"},
      {"sensor.period", "s"},
      {"sensor.noise.sigma", "m"},
      {"loops.loop1_period", "s"},
      {"loops.loop2_period", "s"},
      {"convergence.position_tolerance", "m"},
      {"convergence.virtual_tolerance", "m"},
      {"convergence.max_time", "s"},
      {"metrics.period", "s"},
      {"recording.trajectory_period", "s"},
      {"network.range", "m"},
      {"network.broadcast_period", "s"},
      {"network.staleness", "s"},
      {"network.acquire", "s"},
      {"network.acquire_timeout", "s"}};
  for (const auto& [key, unit] : kFixed) {
    if (path == key) return std::string(unit);
  }
  // Components: planner.<param>, planner.<type>.<param>, and so on.
  const auto param_of = [&](std::string_view prefix) -> std::optional<std::string_view> {
    if (path.substr(0, prefix.size()) != prefix) return std::nullopt;
    std::string_view rest = path.substr(prefix.size());
    if (const auto dot = rest.rfind('.'); dot != std::string_view::npos)
      rest = rest.substr(dot + 1);
    return rest;
  };
  const auto unit_in = [](const auto& registry, std::string_view param) -> std::string {
    for (const auto& e : registry.entries()) {
      if (const ParamSpec* s = find_param(e.params, param)) return s->unit;
    }
    return "";
  };
  if (auto p = param_of("planner.")) return unit_in(planner_registry(), *p);
  if (auto p = param_of("controller.")) return unit_in(coverage_law_registry(), *p);
  if (auto p = param_of("density.")) return unit_in(density_registry(), *p);
  if (auto p = param_of("network.loss.")) return unit_in(loss_registry(), *p);
  if (auto p = param_of("network.delay.")) return unit_in(delay_registry(), *p);
  return "";
}

}  // namespace covsim
