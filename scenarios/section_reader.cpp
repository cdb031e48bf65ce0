#include "scenarios/section_reader.hpp"

#include <algorithm>

#include "scenarios/component_reader.hpp"

namespace covsim {

namespace {
// "noise.sigma": the object "noise" and the key "sigma" in it; "range": no object.
std::pair<std::string, std::string> split_key(const std::string& name) {
  const auto dot = name.find('.');
  if (dot == std::string::npos) return {"", name};
  return {name.substr(0, dot), name.substr(dot + 1)};
}

void add_once(std::vector<std::string>& list, const std::string& s) {
  if (std::find(list.begin(), list.end(), s) == list.end()) list.push_back(s);
}
}  // namespace

void check_section_keys(const JsonValue& v, const ScenarioSection& section,
                        const std::vector<std::string>& other_keys) {
  std::vector<std::string> top = other_keys;
  for (const ConfigKey<Scenario>& k : section.keys) {
    const auto [object, key] = split_key(k.spec.name);
    add_once(top, object.empty() ? key : object);
  }
  v.only_keys(top);
  for (const std::string& name : top) {
    const auto nested = v.find(name);
    if (!nested || std::find(other_keys.begin(), other_keys.end(), name) != other_keys.end())
      continue;
    std::vector<std::string> inner;
    for (const ConfigKey<Scenario>& k : section.keys) {
      const auto [object, key] = split_key(k.spec.name);
      if (object == name) inner.push_back(key);
    }
    if (!inner.empty()) nested->only_keys(inner);
  }
}

void read_section(const JsonValue& v, const ScenarioSection& section, Scenario& s) {
  for (const ConfigKey<Scenario>& k : section.keys) {
    const auto [object, key] = split_key(k.spec.name);
    std::optional<JsonValue> value;
    if (object.empty()) {
      value = v.find(key);
    } else if (const auto nested = v.find(object)) {
      value = k.spec.required() ? nested->at(key) : nested->find(key);
    }
    if (!value) continue;
    const ParamValue x = read_param(*value, k.spec);
    try {
      k.set(s, x);
    } catch (const ParamError& e) {
      value->fail(e.what());
    }
  }
}

nlohmann::ordered_json section_json(const ScenarioSection& section, const Scenario& s) {
  const RunShape shape{*s.environment, s.robot_positions.size()};
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const ConfigKey<Scenario>& k : section.keys) {
    const std::optional<ParamValue> value = k.get(s, shape);
    if (!value) continue;
    const auto [object, key] = split_key(k.spec.name);
    nlohmann::ordered_json& into = object.empty() ? out : out[object];
    into[key] = param_to_json(*value);
  }
  return out;
}

}  // namespace covsim
