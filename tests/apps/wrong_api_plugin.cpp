// A plugin built for another plugin API version: covsim must refuse it, naming both.
#include "sim/plugin.hpp"

extern "C" int covsim_plugin_api_version() {
  return covsim::kPluginApiVersion + 98;
}
extern "C" const char* covsim_plugin_covsim_version() {
  return "9.9.9";
}
extern "C" void covsim_plugin_register(covsim::Registries*) {}
