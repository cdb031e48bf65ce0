#pragma once
// Runs a sweep: every run independent, on N threads, each result saved to
// DIR/runs/<index>.json as soon as it is known (so a rerun skips what is done). The caller
// writes the tables (analysis/sweep/sweep_tables.hpp) and, if it wants them, the charts
// (analysis/figures/sweep_charts.hpp). Results do not depend on N.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "analysis/sweep/sweep_result.hpp"
#include "analysis/sweep/sweep_spec.hpp"
#include "analysis/sweep/sweep_tables.hpp"

namespace covsim {

struct SweepOptions {
  std::size_t jobs = 1;
  bool progress = true;   // lines on stderr
  std::size_t shard = 0;  // run only runs with index % shards == shard
  std::size_t shards = 1;
  bool keep_series = false;  // keep each run's metrics as DIR/runs/<index>.metrics.csv
  // Called once before any run (with the runs found done) and after each run: runs done,
  // of which failed, out of the total (of this shard). Calls do not overlap.
  std::function<void(std::size_t done, std::size_t failed, std::size_t total)> on_progress = {};
};

// Throws std::runtime_error if DIR already holds a different sweep.
std::vector<SweepResult> run_sweep(const SweepSpec& spec, const std::filesystem::path& dir,
                                   const SweepOptions& options);

// Combines the results of sweep folders (shards of one sweep) into `out`: its runs/,
// sweep.json, runs.csv and summary.csv, as one sweep of the whole would give. Throws
// std::runtime_error if the folders hold different sweeps or runs are missing.
std::vector<SweepResult> merge_sweeps(const std::vector<std::filesystem::path>& dirs,
                                      const std::filesystem::path& out, SweepSpec& merged_spec);

}  // namespace covsim
