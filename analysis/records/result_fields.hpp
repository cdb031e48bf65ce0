#pragma once
// The field tables of covsim's result records (field_table.hpp): final.json and its robots,
// a sweep's per-run record (runs.csv, runs/<i>.json, and the statistics of summary.csv), and
// metrics.csv. Adding a result is adding one row here; every writer, reader and docs check
// follows.
#include "analysis/records/field_table.hpp"
#include "sim/coverage_run.hpp"
#include "sim/metrics_sample.hpp"
#include "sim/metrics_sampler.hpp"

namespace covsim {

const FieldTable<CoverageOutcome>& final_fields();
const FieldTable<RobotOutcome>& robot_fields();
const FieldTable<MetricsSample>& metrics_fields();

// What one run of a sweep records: its outcome and the wall-clock seconds it took.
struct RunMeasures {
  CoverageOutcome outcome;
  CommunicationSummary communication;
  double wall_time = 0.0;
};
const FieldTable<RunMeasures>& run_fields();

}  // namespace covsim
