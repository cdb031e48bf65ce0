#pragma once
// A swept value as words for a chart's label: text as it is ("grid_astar"), null as
// "unlimited", a number with its unit ("0.5 m"), an object by its type first and then each
// other key with its value and unit ("periodic, loop1_period 0.1 s"), an array as its items.
#include <string>

#include <nlohmann/json.hpp>

namespace covsim {

// `path` is the swept parameter's dotted path, for the units of its values.
std::string setting_words(const std::string& path, const nlohmann::json& value);

}  // namespace covsim
