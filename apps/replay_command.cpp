// `covsim replay TRACE`: re-runs the scenario a trace embeds and compares the two runs event
// by event. Exit code 0 if they match, 1 at the first divergence.
#include <fmt/format.h>

#include <memory>
#include <string>

#include "apps/commands.hpp"
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
  auto plugins = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand("replay", "Re-run a traced run and compare it event by event");
  cmd->add_option("TRACE", *trace, "Trace written by covsim run --trace")->required();
  add_plugin_option(cmd, *plugins);
  cmd->callback([trace, plugins] {
    load_plugins(*plugins);
    const ReplayReport r = replay_trace(*trace);
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
    throw std::runtime_error(
        fmt::format("replay of {} diverges at event {}", *trace, r.divergence->index));
  });
}

}  // namespace covsim::app
