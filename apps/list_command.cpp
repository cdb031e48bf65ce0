// `covsim list [planners|laws|loss|delay|densities] [--names]`: every registered component
// with its description and parameters (kind, default, unit, bounds), in the spirit of ns-3's
// attribute listing; `--names` prints the names alone, one per line, for scripts, and
// `--reads-range` keeps the planners whose steps depend on the sensor's range.
#include <fmt/format.h>

#include <functional>
#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/plugin_loader.hpp"
#include "geometry/density_registry.hpp"
#include "net/delay_registry.hpp"
#include "net/loss_registry.hpp"
#include "planners/planner_registry.hpp"
#include "robot/coverage_law_registry.hpp"

namespace covsim::app {

namespace {
// A line on what the entry reads besides its parameters ("" for none).
template <class Entry>
std::string reads(const Entry&) {
  return "";
}
std::string reads(const PlannerEntry& e) {
  return e.reads_range ? "    reads the range sensor: its steps depend on sensor.range\n" : "";
}
std::string reads(const LawEntry& e) {
  return e.autonomous ? "" : "    targets set by a driving program: never converges by itself\n";
}

template <class Entry>
void print(const Registry<Entry>& r, const std::string& heading, const std::string& key,
           bool names_only, const std::function<bool(const Entry&)>& keep = {}) {
  if (names_only) {
    for (const Entry& e : r.entries())
      if (!keep || keep(e)) std::cout << e.name << '\n';
    return;
  }
  std::cout << fmt::format("{} ({}):\n", heading, key);
  for (const Entry& e : r.entries()) {
    if (keep && !keep(e)) continue;
    std::cout << fmt::format("  {}: {}\n", e.name, e.description) << reads(e);
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
    bool reads_range = false;
    bool autonomous = false;
    std::vector<std::string> plugins;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "list", "List the registered planners, coverage laws, loss and delay models and densities");
  cmd->add_option("WHAT", o->what, "planners, laws, loss, delay or densities (default: all)")
      ->check(CLI::IsMember({"planners", "laws", "loss", "delay", "densities"}));
  cmd->add_flag("--names", o->names, "Names only, one per line");
  cmd->add_flag("--reads-range", o->reads_range,
                "Planners only: those whose steps depend on the range sensor's range");
  cmd->add_flag("--autonomous", o->autonomous,
                "Laws only: those that compute their own targets (not set by a driving program)");
  add_plugin_option(cmd, o->plugins);
  cmd->callback([o] {
    load_plugins(o->plugins);
    const bool all = o->what.empty();
    if (all && o->names) throw InputError("list: --names needs WHAT (planners, laws, ...)");
    if (o->reads_range && o->what != "planners")
      throw InputError(
          "list: --reads-range applies to planners only (list planners --reads-range)");
    if (o->autonomous && o->what != "laws")
      throw InputError("list: --autonomous applies to laws only (list laws --autonomous)");
    const auto gap = [&] {
      if (all) std::cout << '\n';
    };
    if (all || o->what == "planners")
      print<PlannerEntry>(planner_registry(), "planners", "\"planner\": {\"type\"}", o->names,
                          o->reads_range ? [](const PlannerEntry& e) { return e.reads_range; }
                                         : std::function<bool(const PlannerEntry&)>{}),
          gap();
    if (all || o->what == "laws")
      print<LawEntry>(coverage_law_registry(), "coverage laws", "\"controller\": {\"type\"}",
                      o->names,
                      o->autonomous ? [](const LawEntry& e) { return e.autonomous; }
                                    : std::function<bool(const LawEntry&)>{}),
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
