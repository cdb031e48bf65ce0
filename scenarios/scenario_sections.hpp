#pragma once
// The fixed sections of a scenario file, each key declared once beside the config it fills
// (robot/coverage_config, recording_config, run_limits, robot_draw) and gathered here by
// section: the loader reads the sections through these keys (section_reader), `covsim
// describe` writes them back, `covsim list sections` prints them and docs/scenario-format.md's
// tables of them are generated from them. Sections that select a component are in
// component_sections.hpp.
#include <string>
#include <string_view>
#include <vector>

#include "core/config_key.hpp"
#include "scenarios/scenario.hpp"

namespace covsim {

struct ScenarioSection {
  std::string path;  // "sensor"
  std::string description;
  ConfigKeys<Scenario> keys;
  // Keys of the same object the loader reads itself ("robots": "positions", "count", "start").
  std::vector<std::string> other_keys;
  bool null_is_absent = false;  // "network": null is the ideal network, as if absent
  ParamSchema schema() const;
};

const std::vector<ScenarioSection>& scenario_sections();
// Throws std::invalid_argument for a path no section has.
const ScenarioSection& scenario_section(std::string_view path);
// The key at a dotted path ("sensor.noise.sigma"), or nullptr.
const ParamSpec* find_section_key(std::string_view path);

}  // namespace covsim
