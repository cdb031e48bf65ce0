// `covsim kernel-demo`: runs the kernel's synthetic example model and prints what it did.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "core/fingerprint.hpp"
#include "core/hash.hpp"
#include "core/kernel_example.hpp"
#include "core/trace.hpp"

namespace covsim::app {

void add_kernel_demo_command(CLI::App& app) {
  struct Options {
    std::uint64_t seed = 1;
    std::uint32_t entities = 8;
    double until = 20.0;
    std::string trace;
  };
  auto opts = std::make_shared<Options>();
  CLI::App* cmd =
      app.add_subcommand("kernel-demo", "Run the event kernel's synthetic example model");
  cmd->add_option("--seed", opts->seed, "Random seed")->capture_default_str();
  cmd->add_option("--entities", opts->entities, "Number of entities")
      ->check(CLI::Range(1u, 100000u))
      ->capture_default_str();
  cmd->add_option("--until", opts->until, "Simulated seconds to run")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--trace", opts->trace, "Write the event trace to this file");
  cmd->callback([opts] {
    Kernel kernel(opts->seed);
    std::unique_ptr<TraceWriter> trace;
    if (!opts->trace.empty()) {
      TraceHeader header;
      header.seed = opts->seed;
      header.scenario_hash = fnv1a64(fmt::format("kernel-demo entities={}", opts->entities));
      try {
        trace = std::make_unique<TraceWriter>(opts->trace, header);
      } catch (const std::exception& e) {
        throw InputError(e.what());
      }
      kernel.attach_trace(trace.get());
    }
    const KernelExampleResult r =
        run_kernel_example(kernel, {opts->entities, SimTime::from_seconds(opts->until)});
    if (trace) trace->commit();
    fmt::print("events {}\nmessages {}\ntimeouts {}\nsim_time {:.9f}\nfingerprint {}\n", r.events,
               r.messages, r.timeouts, r.end_time.seconds(), Fingerprint::to_hex(r.fingerprint));
    if (trace) fmt::print("trace {}\n", opts->trace);
  });
}

}  // namespace covsim::app
