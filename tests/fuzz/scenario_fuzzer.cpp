// libFuzzer target: any bytes as a scenario file. Bad input must end in a ScenarioError (the
// CLI's exit 2); a crash, a sanitizer report, a hang or any other exception is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/geometry_error.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json json = covsim::parse_json(text, "fuzz.json");
    const covsim::Scenario s = covsim::parse_scenario(json, "fuzz.json", ".");
    (void)s;
  } catch (const covsim::ScenarioError&) {
  }
  return 0;
}
