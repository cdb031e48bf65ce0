#include "apps/scenario_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <stdexcept>

#include "apps/input_error.hpp"
#include "scenarios/scenario_override.hpp"

namespace covsim::app {

std::uint64_t parse_seed(const std::string& text, const std::string& option) {
  std::uint64_t v = 0;
  const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c));
  });
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (!digits || ec != std::errc() || end != text.data() + text.size()) {
    throw InputError(fmt::format(
        "{}: expected a whole number from 0 to 18446744073709551615, found \"{}\"", option, text));
  }
  return v;
}

void ScenarioOptions::add_to(CLI::App* cmd, const std::string& scenario_help) {
  cmd->add_option("SCENARIO", file, scenario_help)->required();
  cmd->add_option("--seed", seed,
                  "Seed, replacing the scenario's (what it draws and the run's randomness)");
  cmd->add_option("--set", sets,
                  "PATH=VALUE: set a dotted path of the scenario as a sweep does "
                  "(--set network.loss.model=bernoulli --set network.loss.p=0.3 --set "
                  "sensor.range=null); repeatable")
      ->allow_extra_args(false);
}

Scenario ScenarioOptions::load() const {
  std::vector<ScenarioOverride> overrides;
  for (const std::string& s : sets) {
    try {
      overrides.push_back(parse_override(s));
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
  }
  if (!seed.empty()) {
    const std::uint64_t s = parse_seed(seed);
    overrides.push_back(ScenarioOverride{"seed", s, "--seed " + seed});
  }
  return load_scenario(file, overrides);
}

}  // namespace covsim::app
