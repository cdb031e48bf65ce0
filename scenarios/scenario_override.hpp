#pragma once
// An override of a scenario: a dotted path ("network.loss.p") set to a JSON value, as a
// sweep's settings, `covsim run --set` and Python's Scenario.set make them. The result is
// validated as the file would be.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scenarios/scenario.hpp"

namespace covsim {

struct ScenarioOverride {
  std::string path;  // dotted
  nlohmann::json value;
  std::string as_typed;  // "--set network.loss.p=0.3", to name it in errors
};

// Empty if `path` is a dotted path like "network.loss.p"; else what is wrong with it.
std::string dotted_path_error(std::string_view path);
// Sets a dotted path in a JSON object, creating objects on the way.
void set_dotted(nlohmann::json& j, const std::string& path, const nlohmann::json& value);
// Sets a dotted path of a scenario (set_dotted), as overrides do. Setting a component's type
// key to another type (robots.localization.type=exact where it was tracking) moves the old
// type's parameters that the new one lacks into the section's block for the old type
// ("tracking": {...}), where they wait for runs of that type: the section stays valid, and a
// sweep over the types keeps each one's parameters.
void override_scenario(nlohmann::json& scenario, const std::string& path,
                       const nlohmann::json& value);
// "PATH=VALUE": VALUE is JSON (0.3, null, true, "text", [1, 2], {"p": 0.1}), or a bare word
// of letters, digits and _ . - taken as a string (grid_astar). Throws std::invalid_argument
// saying what is wrong.
ScenarioOverride parse_override(std::string_view text, std::string_view option = "--set");
// Reads a scenario file with the overrides applied in order. An error at or under an
// overridden path names the override first: "--set network.loss.p=2: FILE: $.network.loss.p:
// expected ...".
Scenario load_scenario(const std::filesystem::path& file,
                       const std::vector<ScenarioOverride>& overrides);

}  // namespace covsim
