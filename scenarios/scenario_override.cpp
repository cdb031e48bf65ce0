#include "scenarios/scenario_override.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "scenarios/component_sections.hpp"
#include "scenarios/input_file.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim {

std::string dotted_path_error(std::string_view path) {
  if (path.empty() || path.front() == '.' || path.back() == '.' ||
      path.find("..") != std::string_view::npos ||
      path.find_first_of(" \t\n=[]\"") != std::string_view::npos) {
    return fmt::format("\"{}\" is not a dotted path like \"network.loss.p\"", path);
  }
  return "";
}

void set_dotted(nlohmann::json& j, const std::string& dotted, const nlohmann::json& value) {
  nlohmann::json* at = &j;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = dotted.find('.', start);
    const std::string key =
        dotted.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!at->is_object()) *at = nlohmann::json::object();
    if (dot == std::string::npos) {
      (*at)[key] = value;
      return;
    }
    at = &(*at)[key];
    start = dot + 1;
  }
}

void override_scenario(nlohmann::json& j, const std::string& path, const nlohmann::json& value) {
  for_each_component_section([&](const auto& row) {
    if (path != row.path + "." + row.type_key || !value.is_string()) return;
    // The section, if the scenario has it.
    nlohmann::json* section = &j;
    for (std::size_t start = 0; section != nullptr && start <= row.path.size();) {
      const std::size_t dot = std::min(row.path.find('.', start), row.path.size());
      const auto it = section->is_object() ? section->find(row.path.substr(start, dot - start))
                                           : section->end();
      section = section->is_object() && it != section->end() ? &*it : nullptr;
      start = dot + 1;
    }
    if (section == nullptr || !section->is_object()) return;
    const auto t = section->find(row.type_key);
    const std::optional<std::string> old =
        t != section->end()
            ? (t->is_string() ? std::optional(t->template get<std::string>()) : std::nullopt)
            : row.default_type;
    const auto* from = old ? row.registry().find(*old) : nullptr;
    const auto* to = row.registry().find(value.template get<std::string>());
    if (from == nullptr || to == nullptr || from == to) return;  // the loader judges the rest
    nlohmann::json moved = nlohmann::json::object();
    for (auto it = section->begin(); it != section->end();) {
      if (find_param(from->params, it.key()) != nullptr &&
          find_param(to->params, it.key()) == nullptr) {
        moved[it.key()] = *it;
        it = section->erase(it);
      } else {
        ++it;
      }
    }
    if (moved.empty()) return;
    nlohmann::json& block = (*section)[*old];
    if (!block.is_object()) block = nlohmann::json::object();
    for (auto& [key, v] : moved.items())
      if (!block.contains(key)) block[key] = v;  // what the block set already stands
  });
  set_dotted(j, path, value);
}

ScenarioOverride parse_override(std::string_view text, std::string_view option) {
  ScenarioOverride o;
  o.as_typed = fmt::format("{} {}", option, text);
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos)
    throw std::invalid_argument(fmt::format("{}: expected PATH=VALUE", o.as_typed));
  o.path = std::string(text.substr(0, eq));
  if (const std::string e = dotted_path_error(o.path); !e.empty())
    throw std::invalid_argument(fmt::format("{}: {}", o.as_typed, e));
  const std::string value(text.substr(eq + 1));
  if (nlohmann::json::accept(value)) {
    try {  // strictly: no duplicate keys, bounded depth
      o.value = parse_json(value, o.as_typed);
    } catch (const ScenarioError& e) {
      throw std::invalid_argument(e.what());
    }
  } else {
    const bool word = !value.empty() && std::all_of(value.begin(), value.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
    if (!word) {
      throw std::invalid_argument(fmt::format(
          "{}: the value is neither JSON nor a plain word (quote text with spaces as JSON: "
          "'\"...\"')",
          o.as_typed));
    }
    o.value = value;
  }
  return o;
}

Scenario load_scenario(const std::filesystem::path& file,
                       const std::vector<ScenarioOverride>& overrides) {
  InputFile in = read_input(file);
  nlohmann::json& j = in.json;
  for (const ScenarioOverride& o : overrides)
    override_scenario(j, o.path, o.value);
  try {
    return parse_scenario(j, in.source, file.parent_path());
  } catch (const ScenarioError& e) {
    // The last override at, under or above the error's place is the one to blame.
    for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
      const std::string at = "$." + o->path;
      const auto under = [](const std::string& a, const std::string& b) {
        return a.size() >= b.size() && a.compare(0, b.size(), b) == 0 &&
               (a.size() == b.size() || a[b.size()] == '.' || a[b.size()] == '[');
      };
      if (!e.path().empty() && (under(e.path(), at) || (e.path() != "$" && under(at, e.path()))))
        throw ScenarioError(o->as_typed + ": " + e.file(), e.path(), e.detail());
    }
    throw in.located(e);  // the value is the file's own
  }
}

}  // namespace covsim
