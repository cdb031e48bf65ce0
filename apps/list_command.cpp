// `covsim list [planners|laws|loss|delay|densities] [--names]`: every registered component
// with its description and parameters (kind, default, unit, bounds), in the spirit of ns-3's
// attribute listing; `--names` prints the names alone, one per line, for scripts.
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/plugin_loader.hpp"
#include "core/geometry/density_registry.hpp"
#include "net/delay_registry.hpp"
#include "net/loss_registry.hpp"
#include "planners/planner_registry.hpp"
#include "robot/coverage_law_registry.hpp"

namespace covsim::app {

namespace {
template <class Entry>
void print(const Registry<Entry>& r, const std::string& heading, const std::string& key,
           bool names_only) {
  if (names_only) {
    for (const Entry& e : r.entries())
      std::cout << e.name << '\n';
    return;
  }
  std::cout << fmt::format("{} ({}):\n", heading, key);
  for (const Entry& e : r.entries()) {
    std::cout << fmt::format("  {}: {}\n", e.name, e.description);
    if (e.params.empty())
      std::cout << "    (no parameters)\n";
    else
      std::cout << describe(e.params, "    ");
  }
}
}  // namespace

void add_list_command(CLI::App& app) {
  struct Options {
    std::string what;
    bool names = false;
    std::vector<std::string> plugins;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "list", "List the registered planners, coverage laws, loss and delay models and densities");
  cmd->add_option("WHAT", o->what, "planners, laws, loss, delay or densities (default: all)")
      ->check(CLI::IsMember({"planners", "laws", "loss", "delay", "densities"}));
  cmd->add_flag("--names", o->names, "Names only, one per line");
  add_plugin_option(cmd, o->plugins);
  cmd->callback([o] {
    load_plugins(o->plugins);
    const bool all = o->what.empty();
    if (all && o->names) throw InputError("list: --names needs WHAT (planners, laws, ...)");
    const auto gap = [&] {
      if (all) std::cout << '\n';
    };
    if (all || o->what == "planners")
      print(planner_registry(), "planners", "\"planner\": {\"type\"}", o->names), gap();
    if (all || o->what == "laws")
      print(coverage_law_registry(), "coverage laws", "\"controller\": {\"type\"}", o->names),
          gap();
    if (all || o->what == "loss")
      print(loss_registry(), "loss models", "\"network\": {\"loss\": {\"model\"}}", o->names),
          gap();
    if (all || o->what == "delay")
      print(delay_registry(), "delay models", "\"network\": {\"delay\": {\"model\"}}", o->names),
          gap();
    if (all || o->what == "densities")
      print(density_registry(), "densities", "\"density\": {\"type\"}", o->names);
  });
}

}  // namespace covsim::app
