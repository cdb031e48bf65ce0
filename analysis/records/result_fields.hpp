#pragma once
// The field tables of covsim's result records (field_table.hpp). final.json's and a sweep's
// per-run record (runs.csv, runs/<i>.json, and the statistics of summary.csv) are derived
// from the one table of measures (measure.hpp); final.json's robots and metrics.csv have a
// table each. Adding a result is adding one row; every writer, reader and docs check follows.
#include "analysis/records/field_table.hpp"
#include "analysis/records/measure.hpp"
#include "sim/metrics_sample.hpp"

namespace covsim {

// The measures of the outcome, named by their JSON paths, in final.json's order.
const FieldTable<CoverageOutcome>& final_fields();
// The measures a sweep records, named by their columns, in runs.csv's order.
const FieldTable<RunMeasures>& run_fields();
const FieldTable<RobotOutcome>& robot_fields();
const FieldTable<MetricsSample>& metrics_fields();

}  // namespace covsim
