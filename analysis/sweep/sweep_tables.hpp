#pragma once
// A sweep's tables: DIR/runs.csv (one row per run: its parameters, seed, measures and error)
// and DIR/summary.csv (one row per setting: mean, spread, quartiles and modes of every
// summarised measure), each with its columns' units beside it (FILE-metadata.json, CSVW).
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/records/csv_metadata.hpp"
#include "analysis/sweep/sweep_result.hpp"
#include "analysis/sweep/sweep_spec.hpp"

namespace covsim {

// The measures summarised per setting, in this order, as they appear in summary.csv: the run
// fields marked summarized.
std::vector<std::string> sweep_metrics();

// The runs of one setting that its statistics count: failed runs left out, and of runs
// with one fingerprint (seeds that drew nothing different: fixed starts and no random model)
// the first alone, so that n identical runs are not taken for n that agreed.
std::vector<const SweepResult*> distinct_runs(const std::vector<const SweepResult*>& runs);
// One line for each setting whose seeds gave identical runs (at most `shown`, then how many
// more), for stderr; none when every seed's run differs.
std::vector<std::string> identical_seed_warnings(const SweepSpec& spec,
                                                 const std::vector<SweepResult>& results,
                                                 std::size_t shown = 5);

// A swept value as a CSV cell: strings bare, null as "null", the rest as JSON.
std::string csv_value(const nlohmann::json& v);

// The columns of runs.csv and of summary.csv, with their units, in order: the header and
// the CSVW metadata written beside each (runs.csv-metadata.json) come from these.
std::vector<CsvColumn> runs_columns(const SweepSpec& spec);
std::vector<CsvColumn> summary_columns(const SweepSpec& spec);

void write_runs_csv(const std::filesystem::path& file, const SweepSpec& spec,
                    const std::vector<SweepResult>& results);
void write_summary_csv(const std::filesystem::path& file, const SweepSpec& spec,
                       const std::vector<SweepResult>& results);

}  // namespace covsim
