// Sweep throughput: runs per second of a sweep of u_shape runs (10% message loss, so every
// seed is a different run) with 1 and 2 jobs. Real time, as the work is on other threads.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/sweep/sweep_runner.hpp"

namespace {

void BM_SweepThroughput(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("covsim-bench-sweep-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "sweep.json")
      << R"({"scenario": ")" << COVSIM_SOURCE_DIR
      << R"(/scenarios/u_shape.json", "grid": {"network.loss.model": ["bernoulli"],
      "network.loss.p": [0.1]}, "seeds": {"count": 16}})";
  const covsim::SweepSpec spec = covsim::load_sweep(dir / "sweep.json");
  const auto jobs = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    fs::remove_all(dir / "out");  // no resuming: every iteration runs everything
    const auto results =
        covsim::run_sweep(spec, dir / "out", covsim::SweepOptions{jobs, false, 0, 1});
    benchmark::DoNotOptimize(results.size());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(spec.runs().size()));
  fs::remove_all(dir);
}

}  // namespace

BENCHMARK(BM_SweepThroughput)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
