#pragma once
// The options of a command that takes a scenario file: --seed (replacing the scenario's) and
// --set PATH=VALUE (a dotted path set as a sweep sets it, repeatable), applied to the file's
// JSON before it is validated, so that `--set` equals editing the file.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/scenario.hpp"

namespace covsim::app {

struct ScenarioOptions {
  std::string file;
  std::string seed;  // as typed; checked by load()
  std::vector<std::string> sets;

  // Adds SCENARIO, --seed and --set to a command.
  void add_to(CLI::App* cmd, const std::string& scenario_help);
  // The scenario with the options applied; bad options are InputErrors naming the option,
  // a bad result a ScenarioError naming the option that caused it.
  Scenario load() const;
};

// A seed as typed: digits only, up to 2^64 - 1. Throws InputError naming the option.
std::uint64_t parse_seed(const std::string& text, const std::string& option = "--seed");

}  // namespace covsim::app
