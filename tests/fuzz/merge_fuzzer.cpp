// libFuzzer target: any bytes as a shard's sweep.json for `covsim merge`. What is not a sweep
// covsim wrote must end in an exception merge reports as bad input (a ScenarioError naming the
// file: nlohmann's type and key errors and std::invalid_argument are turned into one); what
// is read must hold one value per parameter in every setting. A crash, a sanitizer report or
// a hang is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "analysis/sweep/sweep_spec.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json j;
  try {
    j = covsim::parse_json(text, "sweep.json");
  } catch (const covsim::ScenarioError&) {
    return 0;
  }
  try {
    const covsim::SweepSpec spec = covsim::sweep_from_json(j);
    for (const auto& setting : spec.settings)
      if (setting.size() != spec.parameters.size()) __builtin_trap();
    if (spec.runs().size() != spec.settings.size() * spec.seeds.size()) __builtin_trap();
  } catch (const nlohmann::json::exception&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
