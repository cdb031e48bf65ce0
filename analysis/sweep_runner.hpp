#pragma once
// Runs a sweep: every run independent, on N threads, each result saved to
// DIR/runs/<index>.json as soon as it is known (so a rerun skips what is done), then
// DIR/runs.csv, DIR/summary.csv and plots. Results do not depend on N.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/sweep_spec.hpp"

namespace covsim {

struct SweepResult {
  std::size_t index = 0;
  std::optional<std::string> error;  // the run failed: why
  bool converged = false;
  double sim_time = 0.0;
  double cost_virtual = 0.0, cost_real = 0.0, cost_real_in_virtual_partition = 0.0;
  double path_length = 0.0;
  double time_to_10_percent = 0.0, time_to_5_percent = 0.0, time_to_1_percent = 0.0;
  std::uint64_t messages_sent = 0, messages_lost = 0, events = 0;
  std::string stop_reason;  // converged, stuck or max_time
  double target_outside_steps = 0.0, stalled_time = 0.0, centroid_distance = 0.0;
  // Seconds; with planner_step_time (microseconds per planner step), the fields that differ
  // between machines and runs.
  double wall_time = 0.0, planner_step_time = 0.0;
  std::string fingerprint;
};

struct SweepOptions {
  std::size_t jobs = 1;
  bool progress = true;   // lines on stderr
  std::size_t shard = 0;  // run only runs with index % shards == shard
  std::size_t shards = 1;
};

// Throws std::runtime_error if DIR already holds a different sweep.
std::vector<SweepResult> run_sweep(const SweepSpec& spec, const std::filesystem::path& dir,
                                   const SweepOptions& options);

// Combines the results of sweep folders (shards of one sweep) into `out`: its runs/,
// sweep.json, runs.csv, summary.csv and plots, as one sweep of the whole would give.
// Throws std::runtime_error if the folders hold different sweeps or runs are missing.
std::vector<SweepResult> merge_sweeps(const std::vector<std::filesystem::path>& dirs,
                                      const std::filesystem::path& out, SweepSpec& merged_spec);

// The metrics summarised per setting, in this order, as they appear in summary.csv.
const std::vector<std::string>& sweep_metrics();
double metric_value(const SweepResult& r, const std::string& metric);

void write_runs_csv(const std::filesystem::path& file, const SweepSpec& spec,
                    const std::vector<SweepResult>& results);
void write_summary_csv(const std::filesystem::path& file, const SweepSpec& spec,
                       const std::vector<SweepResult>& results);
// One SVG per (metric, numeric parameter): mean with a 95% confidence band, one line per
// value of `group` (a swept parameter; the others pooled), or without one, per combination
// of the other varying parameters. Returns the files written. Throws std::invalid_argument
// for a group that is not swept.
std::vector<std::filesystem::path> write_sweep_plots(const std::filesystem::path& dir,
                                                     const SweepSpec& spec,
                                                     const std::vector<SweepResult>& results,
                                                     const std::string& group = "");

}  // namespace covsim
