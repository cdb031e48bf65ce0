#pragma once
// Reading a component's JSON section through the registry of its extension point:
//
//   "planner": {"type": "potential_field", "influence": 0.5,
//               "grid_astar": {"resolution": 0.05}}
//
// The type key names a registered component; the section's other keys are that component's
// parameters, checked against its schema (a key no parameter of that type has is an error
// that says which type has it); a sub-object named after any registered type holds that
// type's parameters, checked too, so that a sweep can vary the type and carry each type's
// parameters (planner.grid_astar.resolution). Errors name the file, the JSON path and what
// was expected.
#include <optional>
#include <string>
#include <vector>

#include "core/registry.hpp"
#include "scenarios/component_sections.hpp"
#include "scenarios/json_reader.hpp"

namespace covsim {

// One value checked against its spec: kind, bounds, null (an error names its path and what
// was expected).
ParamValue read_param(const JsonValue& v, const ParamSpec& spec);
// A value as JSON, and the JSON form of parameter values (the inverse of read_params).
nlohmann::ordered_json param_to_json(const ParamValue& v);
// Values of a schema's parameters from an object; keys in `other_keys` are skipped.
Params read_params(const JsonValue& section, const ParamSchema& schema,
                   const std::vector<std::string>& other_keys = {});
nlohmann::ordered_json params_to_json(const Params& p);

struct ComponentChoice {
  std::string type;
  Params params;  // validated, with the schema's constant defaults filled in
};

// The component a section selects. An absent type key takes default_type (a required key
// when it is unset). `section_keys` belong to the section itself, whatever the type (the
// controller's projection policy): the caller reads them.
ComponentChoice read_component(const JsonValue& section,
                               const std::vector<const ComponentInfo*>& registered,
                               const std::string& kind, const std::string& type_key,
                               const std::optional<std::string>& default_type,
                               const std::vector<std::string>& section_keys = {});

template <class Entry>
ComponentChoice read_component(const JsonValue& section, const Registry<Entry>& registry,
                               const std::string& type_key,
                               const std::optional<std::string>& default_type = std::nullopt,
                               const std::vector<std::string>& section_keys = {}) {
  std::vector<const ComponentInfo*> infos;
  for (const Entry& e : registry.entries())
    infos.push_back(&e);
  return read_component(section, infos, registry.kind(), type_key, default_type, section_keys);
}

// The component a section of the table (component_sections.hpp) selects.
template <class Entry>
ComponentChoice read_component(const JsonValue& section, const ComponentSection<Entry>& row,
                               const std::vector<std::string>& section_keys = {}) {
  return read_component(section, row.registry(), row.type_key, row.default_type, section_keys);
}

// A factory's ParamError as a ScenarioError at the parameter's JSON path in the section.
[[noreturn]] void fail_param(const JsonValue& section, const ParamError& e);

}  // namespace covsim
