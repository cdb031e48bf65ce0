// The cost of a run's outputs: the same run of N robots at constant density (a random-env
// scenario, 5 simulated seconds) with everything `covsim run` records on (trajectory.csv,
// metrics.csv and the metrics sampler behind it, the figures' tracks), the same with
// trajectory.csv.gz (gzip) instead, against none.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "analysis/records/robot_track.hpp"
#include "analysis/records/run_recorder.hpp"
#include "scenarios/random_environment.hpp"
#include "scenarios/scenario.hpp"
#include "sim/coverage_run.hpp"

namespace {

covsim::Scenario scenario_of(std::size_t n) {
  covsim::RandomEnvironmentSpec spec;
  spec.robots = static_cast<std::uint32_t>(n);
  spec.size = 0.4 * std::sqrt(static_cast<double>(n));  // about 6 robots per m² of the square
  nlohmann::ordered_json json = covsim::random_environment(spec);
  json["convergence"] = {{"max_time", 5.0}};
  json.erase("recording");
  return covsim::parse_scenario(nlohmann::json::parse(json.dump()), "random", ".");
}

void BM_RunNoOutputs(benchmark::State& state) {
  const covsim::Scenario s = scenario_of(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(covsim::run_coverage(s).fingerprint);
}

void run_with_outputs(benchmark::State& state, bool compress) {
  const covsim::Scenario s = scenario_of(static_cast<std::size_t>(state.range(0)));
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "covsim-bench-run";
  std::filesystem::create_directories(dir);
  covsim::RecordingConfig recording;
  recording.compress = compress;
  for (auto _ : state) {
    covsim::RunRecorder recorder(dir, s.robot_positions, recording,
                                 covsim::track_tolerance(s.environment->diameter()));
    benchmark::DoNotOptimize(covsim::run_coverage(s, &recorder).fingerprint);
    recorder.commit();
  }
  // What one iteration wrote, to compare the two formats' sizes.
  state.counters["trajectory_bytes"] =
      static_cast<double>(std::filesystem::file_size(dir / covsim::trajectory_file_name(compress)));
  std::filesystem::remove_all(dir);
}

void BM_RunOutputs(benchmark::State& state) {
  run_with_outputs(state, false);
}

void BM_RunOutputsCompressed(benchmark::State& state) {
  run_with_outputs(state, true);
}

}  // namespace

BENCHMARK(BM_RunNoOutputs)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RunOutputs)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RunOutputsCompressed)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
