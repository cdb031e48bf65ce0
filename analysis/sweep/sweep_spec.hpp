#pragma once
// A sweep: a scenario, parameters to vary (dotted JSON paths into it) and seeds. Every
// combination of the grid's values (and each row of "zip", whose lists vary together) runs
// with every seed; the seed replaces the scenario's "seed". See docs/sweeps.md.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace covsim {

struct SweepRun {
  std::size_t index = 0;    // position in the sweep, fixed by the file alone
  std::size_t setting = 0;  // which combination of parameter values
  std::uint64_t seed = 0;
  std::vector<nlohmann::json> values;  // one per parameter, in SweepSpec::parameters order
};

// The most runs (settings × seeds) a sweep may hold: a larger grid is refused when read,
// before anything is built for it.
inline constexpr std::size_t kMaxSweepRuns = 1'000'000;

struct SweepSpec {
  std::string source;
  nlohmann::json scenario;                            // the base scenario
  std::filesystem::path scenario_dir;                 // for files the scenario names
  std::vector<std::string> parameters;                // grid keys in file order, then zip keys
  std::vector<std::vector<nlohmann::json>> settings;  // values per setting
  std::vector<std::uint64_t> seeds;
  std::vector<SweepRun> runs() const;  // settings outer, seeds inner
  // The scenario JSON of one run: the base with the run's values and seed put in.
  nlohmann::json scenario_for(const SweepRun& run) const;
};

// Throws ScenarioError naming the file, the JSON path and what was expected.
SweepSpec load_sweep(const std::filesystem::path& file);
// The resolved sweep, as kept in an output folder (DIR/sweep.json), and back.
nlohmann::json to_json(const SweepSpec& spec);
SweepSpec sweep_from_json(const nlohmann::json& j);

}  // namespace covsim
