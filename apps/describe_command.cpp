// `covsim describe SCENARIO [--seed N] [--set PATH=VALUE ...]`: the scenario as it will run,
// every default filled in, as JSON on stdout (it loads back to the same run).
#include <iostream>
#include <memory>

#include "apps/commands.hpp"
#include "apps/plugin_loader.hpp"
#include "apps/scenario_options.hpp"
#include "scenarios/readable_json.hpp"
#include "scenarios/scenario_description.hpp"

namespace covsim::app {

void add_describe_command(CLI::App& app) {
  struct Options {
    ScenarioOptions scenario;
    std::vector<std::string> plugins;
  };
  auto opts = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "describe", "Print the scenario as it will run: every default filled in, robots drawn");
  opts->scenario.add_to(cmd, "Scenario file");
  add_plugin_option(cmd, opts->plugins);
  cmd->callback([opts] {
    load_plugins(opts->plugins);
    std::cout << readable_json(describe_scenario(opts->scenario.load())) << '\n';
  });
}

}  // namespace covsim::app
