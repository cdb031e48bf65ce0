// A plugin for another API version that states no covsim version (a null string): covsim
// must refuse it naming both API versions, not fail on the null.
#include "sim/plugin.hpp"

extern "C" int covsim_plugin_api_version() {
  return covsim::kPluginApiVersion + 1;
}
extern "C" const char* covsim_plugin_covsim_version() {
  return nullptr;
}
extern "C" void covsim_plugin_register(covsim::Registries*) {}
