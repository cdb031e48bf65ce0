// Wall time of a whole run of the paper's controller to convergence.
#include <benchmark/benchmark.h>

#include <stdexcept>
#include <string>

#include "sim/coverage_run.hpp"

namespace {

void BM_RunScenario(benchmark::State& state, const char* file) {
  const covsim::Scenario scenario =
      covsim::load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/" + file);
  for (auto _ : state) {
    const covsim::CoverageOutcome out = covsim::run_coverage(scenario);
    if (!out.converged) state.SkipWithError("the run did not converge");
    benchmark::DoNotOptimize(out.fingerprint);
  }
}

}  // namespace

BENCHMARK_CAPTURE(BM_RunScenario, u_shape, "u_shape.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RunScenario, office, "office.json")->Unit(benchmark::kMillisecond);
