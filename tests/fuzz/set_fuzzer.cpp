// libFuzzer target: any bytes as `--set PATH=VALUE` options, one per line, applied to the
// paper's U-shaped scenario. A bad option must end in std::invalid_argument (parse_override:
// the CLI's exit 2) and a bad result in a ScenarioError; a crash, a sanitizer report, a hang
// or any other exception is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenarios/scenario_error.hpp"
#include "scenarios/scenario_override.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<covsim::ScenarioOverride> overrides;
  try {
    for (std::string line; std::getline(lines, line);)
      overrides.push_back(covsim::parse_override(line, "--set"));
  } catch (const std::invalid_argument&) {
    return 0;
  }
  try {
    (void)covsim::load_scenario(COVSIM_SOURCE_DIR "/scenarios/u_shape.json", overrides);
  } catch (const covsim::ScenarioError&) {
  }
  return 0;
}
