// libFuzzer target: any bytes as a YAML scenario file. Bad input must end in a ScenarioError
// (the CLI's exit 2), placed where the file has the value; what is read must be JSON that
// parse_json reads back the same (covsim writes it out as JSON). A crash, a sanitizer report, a
// hang or any other exception is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenarios/input_file.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"
#include "scenarios/yaml_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  covsim::InputFile in;
  try {
    in = covsim::parse_yaml(text, "fuzz.yaml");
  } catch (const covsim::ScenarioError&) {
    return 0;
  }
  // Read back as JSON (an error here escapes: a bug), it is the same value.
  const std::string json = in.json.dump();
  if (covsim::parse_json(json, "dumped").dump() != json) __builtin_trap();
  try {
    const covsim::Scenario s = covsim::parse_scenario(in.json, in.source, ".");
    (void)s;
  } catch (const covsim::ScenarioError& e) {
    (void)in.located(e);
  }
  return 0;
}
