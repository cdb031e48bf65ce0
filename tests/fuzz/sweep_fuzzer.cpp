// libFuzzer target: any bytes as a sweep file (`covsim sweep FILE`), beside a copy of the
// paper's U-shaped scenario that it may name. What is not a sweep must end in a ScenarioError
// (the CLI's exit 2); what is read must hold one value per parameter in every setting, and
// every run's scenario must load. A crash, a sanitizer report, a hang or any other exception
// is a bug.
//
// Every setting of a sweep is loaded once when it is read (about a millisecond for the U
// room), so inputs whose grid holds more than 64 settings are skipped: the limit on a
// sweep's size is checked by the unit tests, and a fuzz input must stay well inside
// libFuzzer's timeout. A scenario named by path must be a plain file name in the scratch
// folder (not /dev/zero or a file elsewhere).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/sweep/sweep_spec.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"

namespace fs = std::filesystem;

namespace {

fs::path scratch;

// Settings the grid and zip would make, as far as can be told before the file is read; 0 for
// an input that is not shaped like a sweep (the loader refuses it quickly).
double planned_settings(const nlohmann::json& j) {
  if (!j.is_object()) return 0;
  double settings = 1;
  if (const auto grid = j.find("grid"); grid != j.end() && grid->is_object()) {
    for (const auto& [key, values] : grid->items())
      settings *= values.is_array() ? static_cast<double>(values.size()) : 1.0;
  }
  if (const auto zip = j.find("zip"); zip != j.end() && zip->is_object()) {
    for (const auto& [key, values] : zip->items())
      if (values.is_array()) settings *= static_cast<double>(values.size());
  }
  return settings;
}

bool plain_name(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("scenario") || !j["scenario"].is_string()) return true;
  const std::string name = j["scenario"].get<std::string>();
  return name.find('/') == std::string::npos && name != "..";
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  char pattern[] = "/tmp/covsim-sweep-fuzz-XXXXXX";
  if (mkdtemp(pattern) == nullptr) std::abort();
  scratch = pattern;
  fs::copy_file(COVSIM_SOURCE_DIR "/scenarios/u_shape.json", scratch / "u_shape.json");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json j = covsim::parse_json(text, "sweep.json");
    if (planned_settings(j) > 64 || !plain_name(j)) return 0;
  } catch (const covsim::ScenarioError&) {
    // Not JSON: the loader must refuse it the same way.
  }
  const fs::path file = scratch / "sweep.json";
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  try {
    const covsim::SweepSpec spec = covsim::load_sweep(file);
    if (spec.settings.empty() || spec.seeds.empty()) __builtin_trap();
    for (const auto& setting : spec.settings)
      if (setting.size() != spec.parameters.size()) __builtin_trap();
    const auto runs = spec.runs();
    if (runs.size() != spec.settings.size() * spec.seeds.size()) __builtin_trap();
    // Validated when read: the first run of each setting loads (its seed is a scenario's).
    (void)covsim::parse_scenario(spec.scenario_for(runs.back()), spec.source, spec.scenario_dir);
  } catch (const covsim::ScenarioError&) {
  }
  return 0;
}
