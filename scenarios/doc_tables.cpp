#include "scenarios/doc_tables.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "net/channel_registry.hpp"
#include "robot/collision_avoidance_registry.hpp"
#include "robot/kinematics_registry.hpp"
#include "robot/localization_registry.hpp"
#include "scenarios/scenario_sections.hpp"

namespace covsim {

namespace {
// "<!-- begin sensor -->", "<!-- end sensor -->": each a line of its own.
std::string marker(const char* which, const std::string& name) {
  return fmt::format("<!-- {} {} -->", which, name);
}

// Where the table of `name` starts and ends (after its begin line, at its end line).
std::optional<std::pair<std::size_t, std::size_t>> span(const std::string& text,
                                                        const std::string& name) {
  const std::string begin = marker("begin", name) + "\n";
  const auto b = text.find(begin);
  if (b == std::string::npos) return std::nullopt;
  const auto e = text.find(marker("end", name) + "\n", b);
  if (e == std::string::npos) return std::nullopt;
  return std::pair{b + begin.size(), e};
}
}  // namespace

std::vector<DocTable> scenario_doc_tables() {
  std::vector<DocTable> out;
  for (const ScenarioSection& s : scenario_sections())
    out.push_back({s.path, markdown_table(s.schema())});
  // A channel model's keys sit in network.channel beside its type (ns3_wifi's radio).
  for (const ChannelEntry& e : channel_registry().entries()) {
    if (!e.params.empty()) out.push_back({"network.channel." + e.name, markdown_table(e.params)});
  }
  // And a collision avoidance's in robots.avoidance (orca's horizon).
  for (const AvoidanceEntry& e : collision_avoidance_registry().entries()) {
    if (!e.params.empty()) out.push_back({"robots.avoidance." + e.name, markdown_table(e.params)});
  }
  // And a kinematics' in robots.kinematics (a differential drive's wheel base).
  for (const KinematicsEntry& e : kinematics_registry().entries()) {
    if (!e.params.empty()) out.push_back({"robots.kinematics." + e.name, markdown_table(e.params)});
  }
  // And a localization's in robots.localization (a tracking system's rate).
  for (const LocalizationEntry& e : localization_registry().entries()) {
    if (!e.params.empty())
      out.push_back({"robots.localization." + e.name, markdown_table(e.params)});
  }
  return out;
}

std::optional<std::string> doc_table_in(const std::string& text, const std::string& name) {
  const auto at = span(text, name);
  if (!at) return std::nullopt;
  return text.substr(at->first, at->second - at->first);
}

std::string with_doc_table(const std::string& text, const DocTable& table) {
  const auto at = span(text, table.name);
  if (!at)
    throw std::invalid_argument(fmt::format("no lines \"{}\" and \"{}\" around a table",
                                            marker("begin", table.name),
                                            marker("end", table.name)));
  return text.substr(0, at->first) + table.markdown + text.substr(at->second);
}

std::string marked(const DocTable& table) {
  return marker("begin", table.name) + "\n" + table.markdown + marker("end", table.name) + "\n";
}

}  // namespace covsim
