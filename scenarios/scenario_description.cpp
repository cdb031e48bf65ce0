#include "scenarios/scenario_description.hpp"

#include <cmath>
#include <optional>
#include <utility>

#include "scenarios/component_reader.hpp"
#include "scenarios/component_sections.hpp"
#include "scenarios/scenario_sections.hpp"
#include "scenarios/section_reader.hpp"

namespace covsim {

namespace {

nlohmann::ordered_json points(const std::vector<Vec2>& ps) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (Vec2 p : ps)
    a.push_back({p.x, p.y});
  return a;
}

// {type_key: type, every parameter}: constant and derived defaults filled in.
template <class Entry>
nlohmann::ordered_json component(const ComponentSection<Entry>& row, const std::string& type,
                                 const Params& params, const Environment& env) {
  const Entry& e = row.registry().at(type);
  nlohmann::ordered_json j{{row.type_key, type}};
  const nlohmann::ordered_json values =
      params_to_json(with_derived(e.params, with_defaults(e.params, params), env));
  for (const auto& [k, v] : values.items())
    j[k] = v;
  return j;
}

// A component section as the file has it (or as its absence means), read through its
// registry again.
template <class Entry>
nlohmann::ordered_json reread(const Scenario& s, const ComponentSection<Entry>& row,
                              const nlohmann::json* section) {
  const nlohmann::json absent =
      row.absent.empty() ? nlohmann::json() : nlohmann::json::parse(row.absent);
  const ComponentChoice c =
      read_component(JsonValue(section ? *section : absent, s.source, "$." + row.path), row);
  return component(row, c.type, c.params, *s.environment);
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
  out["density"] = reread(s, component_section<DensityEntry>(), &s.json.at("density"));
  if (!s.robot_positions.empty()) out["robots"] = {{"positions", points(s.robot_positions)}};
  if (s.seed) out["seed"] = *s.seed;
  out["planner"] =
      component(component_section<PlannerEntry>(), c.planner.type, c.planner.params, env);
  out["controller"] = component(component_section<LawEntry>(), c.law.type, c.law.params, env);
  for (const ScenarioSection& section : scenario_sections()) {
    // Robots exist only in a scenario that has them; a network only in one that has it
    // (without, robots know each other's state at once).
    if (section.path == "robots" && s.robot_positions.empty()) continue;
    if (section.null_is_absent &&
        (!s.json.contains(section.path) || s.json.at(section.path).is_null()))
      continue;
    const nlohmann::ordered_json keys = section_json(section, s);
    for (const auto& [k, v] : keys.items())
      out[section.path][k] = v;
  }
  // Components inside a fixed section (network.loss, robots.avoidance): where the section is.
  for_each_component_section([&](const auto& row) {
    const auto dot = row.path.find('.');
    if (dot == std::string::npos) return;
    const std::string section = row.path.substr(0, dot), key = row.path.substr(dot + 1);
    if (!out.contains(section)) return;
    const nlohmann::json& in = s.json.contains(section) ? s.json.at(section) : nlohmann::json();
    out[section][key] = reread(s, row, in.is_object() && in.contains(key) ? &in.at(key) : nullptr);
  });
  return out;
}

std::string scenario_key_unit(std::string_view path) {
  if (const ParamSpec* spec = find_section_key(path)) return spec->unit;
  // Components: planner.<param>, planner.<type>.<param>, and so on; any type's parameter of
  // that name.
  std::string unit;
  for_each_component_section([&](const auto& row) {
    const std::string prefix = row.path + ".";
    if (!unit.empty() || path.substr(0, prefix.size()) != prefix) return;
    std::string_view param = path.substr(prefix.size());
    if (const auto dot = param.rfind('.'); dot != std::string_view::npos)
      param = param.substr(dot + 1);
    for (const auto& e : row.registry().entries()) {
      if (const ParamSpec* spec = find_param(e.params, param); spec && unit.empty())
        unit = spec->unit;
    }
  });
  return unit;
}

}  // namespace covsim
