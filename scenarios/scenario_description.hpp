#pragma once
// A scenario as it will run (`covsim describe`): every key the loader reads, with every
// default filled in (those derived from the environment computed for it), the rings as
// normalised and robots drawn per seed written as drawn. It loads back to the same run.
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

#include "scenarios/scenario.hpp"

namespace covsim {

nlohmann::ordered_json describe_scenario(const Scenario& scenario);

// The unit of a scenario key given as a dotted path ("sensor.range": "m", "network.loss.p":
// ""), for axis labels; a component's parameter takes its schema's unit (any type that has
// it). Empty for a pure number or an unknown key.
std::string scenario_key_unit(std::string_view path);

}  // namespace covsim
