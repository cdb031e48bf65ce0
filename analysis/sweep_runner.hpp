#pragma once
// Runs a sweep: every run independent, on N threads, each result saved to
// DIR/runs/<index>.json as soon as it is known (so a rerun skips what is done), then
// DIR/runs.csv, DIR/summary.csv and plots. Results do not depend on N.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/canvas.hpp"
#include "analysis/line_chart.hpp"
#include "analysis/sweep_spec.hpp"

namespace covsim {

// One run's record: its measures (run_fields(), by name), or why it failed.
struct SweepResult {
  std::size_t index = 0;
  std::optional<std::string> error;  // the run failed: why
  nlohmann::ordered_json values = nlohmann::ordered_json::object();
  double number(const std::string& field) const;  // NaN if absent
  bool converged() const;
  std::string fingerprint() const;
};

struct SweepOptions {
  std::size_t jobs = 1;
  bool progress = true;   // lines on stderr
  std::size_t shard = 0;  // run only runs with index % shards == shard
  std::size_t shards = 1;
  bool keep_series = false;  // keep each run's metrics as DIR/runs/<index>.metrics.csv
};

// Throws std::runtime_error if DIR already holds a different sweep.
std::vector<SweepResult> run_sweep(const SweepSpec& spec, const std::filesystem::path& dir,
                                   const SweepOptions& options);

// Combines the results of sweep folders (shards of one sweep) into `out`: its runs/,
// sweep.json, runs.csv, summary.csv and plots, as one sweep of the whole would give.
// Throws std::runtime_error if the folders hold different sweeps or runs are missing.
std::vector<SweepResult> merge_sweeps(const std::vector<std::filesystem::path>& dirs,
                                      const std::filesystem::path& out, SweepSpec& merged_spec,
                                      const std::string& group = "",
                                      FigureFormat format = FigureFormat::svg);

// The metrics summarised per setting, in this order, as they appear in summary.csv: the
// run fields marked summarized.
std::vector<std::string> sweep_metrics();

void write_runs_csv(const std::filesystem::path& file, const SweepSpec& spec,
                    const std::vector<SweepResult>& results);
void write_summary_csv(const std::filesystem::path& file, const SweepSpec& spec,
                       const std::vector<SweepResult>& results);
// One chart per (metric, numeric parameter), named "<metric>_vs_<parameter>": mean with a
// 95% confidence band and the runs as dots, one line per value of `group` (a swept
// parameter; the others pooled), or without one, per combination of the other varying
// parameters. Throws std::invalid_argument for a group that is not swept.
struct SweepChart {
  std::string name;
  LineChart chart;
};
std::vector<SweepChart> sweep_charts(const SweepSpec& spec, const std::vector<SweepResult>& results,
                                     const std::string& group = "");
// The charts drawn as DIR/<name>.svg (or .pdf, .png). Returns the files written.
std::vector<std::filesystem::path> write_sweep_plots(const std::filesystem::path& dir,
                                                     const SweepSpec& spec,
                                                     const std::vector<SweepResult>& results,
                                                     const std::string& group = "",
                                                     FigureFormat format = FigureFormat::svg);

}  // namespace covsim
