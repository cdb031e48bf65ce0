// The ns3_wifi channel's cost: a simulated minute of office with N robots run by covsim with
// its ns-3 peer (BM_Ns3Channel), against the same ns-3 traffic alone (BM_Ns3Alone): the frames
// covsim sent the peer in that run, recorded (COVSIM_NS3_RECORD) and replayed into a fresh
// peer (covsim-ns3-peer --replay FILE) with no covsim, no robots and no round trips. Their
// ratio is the coupling's cost (docs/performance.md). Both count wall time (the peer is
// another process) and report simulated seconds per wall second.
#include <benchmark/benchmark.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "net/ns3_wifi_channel.hpp"
#include "scenarios/scenario_override.hpp"
#include "sim/coverage_run.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
constexpr double kSimulatedSeconds = 60.0;

covsim::Scenario office(int n) {
  std::vector<covsim::ScenarioOverride> set{
      {"robots", {{"count", n}, {"start", {{"uniform", true}}}}, "robots={count, start}"},
      {"network.channel", {{"type", "ns3_wifi"}}, "network.channel"},
      // A minute of motion whatever N: the run stops at max_time, not converged.
      {"convergence.max_time", kSimulatedSeconds, "convergence.max_time"},
      {"convergence.position_tolerance", 1e-9, "convergence.position_tolerance"},
      {"convergence.virtual_tolerance", 1e-9, "convergence.virtual_tolerance"}};
  return covsim::load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/office.json", set);
}

// The frames of one run with N robots, recorded once per process.
fs::path recording(int n) {
  const fs::path file =
      fs::temp_directory_path() / ("covsim-bench-ns3-" + std::to_string(n) + ".frames");
  static std::vector<int> recorded;
  if (std::find(recorded.begin(), recorded.end(), n) == recorded.end()) {
    fs::remove(file);
    ::setenv("COVSIM_NS3_RECORD", file.c_str(), 1);
    (void)covsim::run_coverage(office(n));
    ::unsetenv("COVSIM_NS3_RECORD");
    recorded.push_back(n);
  }
  return file;
}

void BM_Ns3Channel(benchmark::State& state) {
  if (!covsim::ns3_peer_program()) {
    state.SkipWithError("covsim was built without ns-3");
    return;
  }
  const covsim::Scenario scenario = office(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const covsim::CoverageOutcome out = covsim::run_coverage(scenario);
    benchmark::DoNotOptimize(out.fingerprint);
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(
      kSimulatedSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_Ns3Alone(benchmark::State& state) {
  const auto peer = covsim::ns3_peer_program();
  if (!peer) {
    state.SkipWithError("covsim was built without ns-3");
    return;
  }
  const std::string frames = recording(static_cast<int>(state.range(0))).string();
  std::string program = peer->string(), flag = "--replay", file = frames;
  char* argv[] = {program.data(), flag.data(), file.data(), nullptr};
  for (auto _ : state) {
    pid_t pid = 0;
    if (::posix_spawn(&pid, argv[0], nullptr, nullptr, argv, environ) != 0) {
      state.SkipWithError("cannot start the peer");
      return;
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      state.SkipWithError("the peer's replay failed");
      return;
    }
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(
      kSimulatedSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_Ns3Channel)->Arg(5)->Arg(30)->Arg(100)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK(BM_Ns3Alone)->Arg(5)->Arg(30)->Arg(100)->UseRealTime()->Unit(benchmark::kSecond);
