#pragma once
// The scenario sections that select a registered component, one row per extension point:
// what `covsim list` calls it, the section's path, the key naming the type, the type an
// absent key means, and the registry. The loader, `covsim describe`, `covsim list`,
// scenario_key_unit and the plugin API (sim/plugin.hpp's Registries) read this table;
// nothing else pairs sections with registries.
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "geometry/density_registry.hpp"
#include "net/channel_registry.hpp"
#include "net/delay_registry.hpp"
#include "net/loss_registry.hpp"
#include "planners/planner_registry.hpp"
#include "robot/collision_avoidance_registry.hpp"
#include "robot/coverage_law_registry.hpp"
#include "robot/kinematics_registry.hpp"
#include "robot/localization_registry.hpp"

namespace covsim {

template <class Entry>
struct ComponentSection {
  std::string listing;  // `covsim list WHAT`: "planners"
  std::string path;     // dotted: "network.loss"
  std::string type_key;
  // The type when the section leaves out its type key; unset: the key is required.
  std::optional<std::string> default_type;
  // What an absent section means, as JSON for `covsim describe`; empty when the config
  // always holds a type (planner, controller) or the section is required (density).
  std::string absent;
  Registry<Entry>& (*registry)();
};

// In the order of sim/plugin.hpp's Registries, which is built from it.
inline const auto& component_sections() {
  static const std::tuple sections{
      ComponentSection<PlannerEntry>{"planners", "planner", "type", PlannerConfig{}.type, "",
                                     planner_registry},
      ComponentSection<LawEntry>{"laws", "controller", "type", LawConfig{}.type, "",
                                 coverage_law_registry},
      ComponentSection<LossEntry>{"loss", "network.loss", "model", std::nullopt,
                                  R"({"model": "none"})", loss_registry},
      ComponentSection<DelayEntry>{"delay", "network.delay", "model", std::nullopt,
                                   R"({"model": "constant", "value": 0.0})", delay_registry},
      ComponentSection<ChannelEntry>{"channels", "network.channel", "type", std::string("abstract"),
                                     R"({"type": "abstract"})", channel_registry},
      ComponentSection<DensityEntry>{"densities", "density", "type", std::nullopt, "",
                                     density_registry},
      ComponentSection<AvoidanceEntry>{"avoidance", "robots.avoidance", "type",
                                       AvoidanceConfig{}.type, R"({"type": "none"})",
                                       collision_avoidance_registry},
      ComponentSection<KinematicsEntry>{"kinematics", "robots.kinematics", "type",
                                        KinematicsConfig{}.type, R"({"type": "single_integrator"})",
                                        kinematics_registry},
      ComponentSection<LocalizationEntry>{"localization", "robots.localization", "type",
                                          LocalizationConfig{}.type, R"({"type": "exact"})",
                                          localization_registry}};
  return sections;
}

template <class Entry>
const ComponentSection<Entry>& component_section() {
  return std::get<ComponentSection<Entry>>(component_sections());
}

// Calls f with each row, in the table's order.
template <class F>
void for_each_component_section(F&& f) {
  std::apply([&](const auto&... s) { (f(s), ...); }, component_sections());
}

}  // namespace covsim
