#pragma once
// The measures of a run, each declared once (measures()): its name, unit, description, how
// it is read from the run and, for final.json read back, written into an outcome. final.json
// and a sweep's runs.csv, runs/<i>.json and summary.csv are derived from the one table
// (result_fields.hpp), and docs/outputs.md lists it, which a test checks.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/records/field_table.hpp"
#include "sim/coverage_run.hpp"
#include "sim/metrics_sampler.hpp"

namespace covsim {

// What one run of a sweep records: its outcome, its communication measures (from its metrics
// samples) and the wall-clock seconds it took.
struct RunMeasures {
  CoverageOutcome outcome;
  CommunicationSummary communication;
  double wall_time = 0.0;
};

// The unit of the coverage cost H = Σ_i ½ ∫_{V_i ∩ Ω} |x − p_i|² φ(x) dx: squared metres of
// distance times square metres of area, times φ's values as the scenario gives them (φ has
// no unit of its own; uniform is 1). Every cost measure, column and figure says this.
inline constexpr const char* kCostUnit = "m⁴·φ";

struct Measure {
  // Dotted. For a measure of the outcome, its JSON path in final.json
  // ("convergence.time_to_10_percent": the key time_to_10_percent of the object convergence).
  std::string name;
  FieldKind kind = FieldKind::number;
  std::string unit;  // "s", "m", "µs"; empty for counts and pure numbers
  std::string description;
  // One of the two: a measure of the outcome (written to final.json), or one that only a
  // sweep's run records (its communication summary, its wall time).
  std::function<nlohmann::ordered_json(const CoverageOutcome&)> of_outcome;
  std::function<nlohmann::ordered_json(const RunMeasures&)> of_run;
  // Writes final.json's value back into an outcome; unset for values derived from others.
  std::function<void(CoverageOutcome&, const nlohmann::json&)> set;
  // Its place among the columns of runs.csv (and keys of runs/<i>.json), which keep the
  // order they were first written in; none for a measure only final.json holds.
  std::optional<int> run_place;
  // Its runs.csv column when not the name's last part (cost.virtual is cost_virtual).
  std::string declared_column;
  // Summarised per setting in summary.csv (mean, spread, quartiles, modes).
  bool summarized = false;
  // Added after records were first written: a final.json without it (an older run folder)
  // reads as the outcome's default, rather than as damaged.
  bool added_later = false;

  bool in_final() const { return static_cast<bool>(of_outcome); }
  // runs.csv's column: declared_column, or the name's last part.
  std::string column() const;
  nlohmann::ordered_json of(const RunMeasures& m) const {
    return of_outcome ? of_outcome(m.outcome) : of_run(m);
  }

  // Declaring a measure: a column of runs.csv at `place` (named `column` when given), in
  // summary.csv, added later.
  Measure in_runs(int place, std::string column = {}) &&;
  Measure in_summary() &&;
  Measure later() &&;
};

// Every measure, in final.json's order (measures only a sweep records beside their kin).
const std::vector<Measure>& measures();

}  // namespace covsim
