#pragma once
// Reading a fixed section of a scenario (scenario_sections.hpp) through its keys' schemas:
// unknown keys, kinds, bounds and null are checked as for a component's parameters, a key of
// a nested object ("noise.sigma") is required in that object when it has no default, and a
// rule a key's config states (ParamError) is reported at the key's JSON path. Keys the file
// leaves out keep the config's defaults.
#include <nlohmann/json.hpp>

#include "scenarios/json_reader.hpp"
#include "scenarios/scenario_sections.hpp"

namespace covsim {

// Fails on a key that is neither the section's nor one of `other_keys`.
void check_section_keys(const JsonValue& v, const ScenarioSection& section,
                        const std::vector<std::string>& other_keys);
// Sets each key the object gives, in the order of declaration.
void read_section(const JsonValue& v, const ScenarioSection& section, Scenario& s);
// The keys as the run uses them, for `covsim describe`: every default filled in.
nlohmann::ordered_json section_json(const ScenarioSection& section, const Scenario& s);

}  // namespace covsim
