// `covsim replay TRACE [--run DIR]`: re-runs the scenario a trace embeds and compares the two
// runs event by event. Exit code 0 if they match, 1 at the first divergence; with the run's
// folder, it also names the first robot state the replay did not reproduce.
#include <fmt/format.h>

#include <memory>
#include <string>

#include "analysis/records/run_files.hpp"
#include "analysis/records/state_difference.hpp"
#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/plugin_loader.hpp"
#include "core/fingerprint.hpp"
#include "sim/trace_replay.hpp"

namespace covsim::app {

namespace {
std::string describe(const std::optional<TraceRecord>& r) {
  if (!r) return "nothing (this run had already ended)";
  const std::string who =
      r->entity == UINT32_MAX ? std::string("all robots") : fmt::format("robot {}", r->entity);
  return fmt::format("t = {:.9f} s, {} for {}, fingerprint {}", r->time.seconds(), r->kind, who,
                     Fingerprint::to_hex(r->fingerprint));
}
}  // namespace

void add_replay_command(CLI::App& app) {
  auto trace = std::make_shared<std::string>();
  auto run = std::make_shared<std::string>();
  auto plugins = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand("replay", "Re-run a traced run and compare it event by event");
  cmd->add_option("TRACE", *trace, "Trace written by covsim run --trace")->required();
  cmd->add_option("--run", *run,
                  "The traced run's folder (covsim run --out): at a divergence, name the first "
                  "robot state (position, virtual generator, targets) that differs");
  add_plugin_option(cmd, *plugins);
  cmd->callback([trace, run, plugins] {
    load_plugins(*plugins);
    // The folder is read first: a bad one is bad input, before a long replay.
    std::vector<TrajectoryRow> recorded;
    if (!run->empty()) {
      try {
        recorded = read_run_files(*run).trajectory;
      } catch (const std::exception& e) {
        throw InputError(
            fmt::format("--run {}: not a run folder covsim can read: {}", *run, e.what()));
      }
    }
    TrajectoryCapture replayed;
    const ReplayReport r = replay_trace(*trace, run->empty() ? nullptr : &replayed);
    if (!r.build_differences.empty()) {
      fmt::print(stderr, "covsim: warning: {} was written by a different build:\n", *trace);
      for (const std::string& d : r.build_differences)
        fmt::print(stderr, "  {}\n", d);
    }
    if (r.matches) {
      fmt::print("replay matches: {} events, fingerprint {}\n", r.events,
                 Fingerprint::to_hex(r.fingerprint));
      return;
    }
    fmt::print("replay diverges at event {}:\n  trace:  {}\n  replay: {}\n", r.divergence->index,
               describe(r.divergence->a), describe(r.divergence->b));
    if (!run->empty()) {
      if (const auto d = first_state_difference(recorded, replayed.rows()))
        fmt::print(
            "  first state that differs: robot {}'s {} at t = {} s: recorded ({}, {}), "
            "replayed ({}, {})\n",
            d->robot, d->what, d->t, d->recorded.x, d->recorded.y, d->replayed.x, d->replayed.y);
      else
        fmt::print(
            "  every robot state {} records agrees up to the divergence: what differs is "
            "not in trajectory.csv (the event's time or kind, a message, a planner's state)\n",
            *run);
    }
    throw std::runtime_error(
        fmt::format("replay of {} diverges at event {}", *trace, r.divergence->index));
  });
}

}  // namespace covsim::app
