#include "analysis/sweep/setting_words.hpp"

#include <fmt/format.h>

#include "scenarios/scenario_description.hpp"

namespace covsim {

std::string setting_words(const std::string& path, const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_null()) return "unlimited";
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number()) {
    const std::string unit = scenario_key_unit(path);
    const std::string number = fmt::format("{:g}", value.get<double>());
    return unit.empty() ? number : number + " " + unit;
  }
  if (value.is_array()) {
    std::string out;
    for (const auto& v : value)
      out += (out.empty() ? "" : ", ") + setting_words(path, v);
    return "[" + out + "]";
  }
  // An object: the key that names its kind first, then the rest in order.
  std::string out, named_by;
  for (const char* kind : {"type", "model", "mode"})
    if (value.contains(kind) && value[kind].is_string()) {
      out = value[kind].get<std::string>();
      named_by = kind;
      break;
    }
  for (const auto& [key, v] : value.items())
    if (key != named_by)
      out += (out.empty() ? "" : ", ") + key + " " + setting_words(path + "." + key, v);
  return out.empty() ? "{}" : out;
}

}  // namespace covsim
