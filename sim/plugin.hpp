#pragma once
// Extending covsim without touching its source. A plugin is a shared library that `covsim
// run|sweep|list ... --plugin FILE` loads before reading the scenario; it adds its
// components to the registries and is then selected by name in a scenario like any
// built-in one. Write the registering function and name it with COVSIM_PLUGIN:
//
//   void register_mine(covsim::Registries& r) { r.planners.add(bug2_entry()); }
//   COVSIM_PLUGIN(register_mine)
//
// and build the library against the installed package's covsim::plugin target (headers
// and flags only: the plugin uses the symbols of the covsim program that loads it, so its
// components land in that program's registries). The plugin API version is checked when
// the plugin loads; a plugin built for another version is refused with both versions named.
// A program that links covsim::covsim adds its components the same way, through
// registries(), and calls run_coverage or run_sweep itself.
#include <tuple>

#include "core/version.hpp"
#include "scenarios/component_sections.hpp"

namespace covsim {

// Changes whenever a registry entry or an extension interface changes incompatibly.
inline constexpr int kPluginApiVersion = 6;

// The registries of component_sections(), by name, for plugins; built from that table (in its
// order, which the members' types check), so that it stays the one list of them.
struct Registries {
  Registry<PlannerEntry>& planners;
  Registry<LawEntry>& laws;
  Registry<LossEntry>& loss;
  Registry<DelayEntry>& delay;
  Registry<ChannelEntry>& channels;
  Registry<DensityEntry>& densities;
  Registry<AvoidanceEntry>& avoidance;
  Registry<KinematicsEntry>& kinematics;
  Registry<LocalizationEntry>& localization;
};

inline Registries registries() {
  return std::apply([](const auto&... row) { return Registries{row.registry()...}; },
                    component_sections());
}

}  // namespace covsim

// The plugin's entry points, with C names so that the loader finds them.
#define COVSIM_PLUGIN(register_function)                          \
  extern "C" int covsim_plugin_api_version() {                    \
    return covsim::kPluginApiVersion;                             \
  }                                                               \
  extern "C" const char* covsim_plugin_covsim_version() {         \
    return covsim::kVersion;                                      \
  }                                                               \
  extern "C" void covsim_plugin_register(covsim::Registries* r) { \
    register_function(*r);                                        \
  }
