#pragma once
// --plugin FILE for the commands that read scenarios: loads shared libraries that register
// components (sim/plugin.hpp) before anything is parsed.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace covsim::app {

void add_plugin_option(CLI::App* cmd, std::vector<std::string>& plugins);
// Throws InputError naming the file: it cannot be loaded, is not a covsim plugin, or was
// built for another plugin API version.
void load_plugins(const std::vector<std::string>& plugins);

}  // namespace covsim::app
