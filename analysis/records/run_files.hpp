#pragma once
// A run's output folder read back: what `covsim run` wrote (scenario.json, final.json,
// trajectory.csv or trajectory.csv.gz, metrics.csv) is enough to redraw its figures and its
// replay.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/records/known_cells.hpp"
#include "analysis/records/planner_map_record.hpp"
#include "analysis/records/robot_track.hpp"
#include "analysis/records/run_recorder.hpp"
#include "sim/coverage_run.hpp"

namespace covsim {

struct RunFiles {
  Scenario scenario;        // from scenario.json, with the original file's name as its source
  CoverageOutcome outcome;  // what final.json holds
  std::vector<TrajectoryRow> trajectory;
  std::vector<MetricsSample> samples;  // the cost columns of metrics.csv
  KnownCells known;                    // map.csv, when the robots mapped Ω
  // planner_map.csv, when the planners kept maps of their own (else empty).
  PlannerMapRecord planner_maps;
  // Each robot's track, as RunRecorder kept it.
  std::vector<RobotTrack> tracks() const;
};

// The scenario as a run folder keeps it: the scenario's JSON with files it names made
// absolute, so the copy loads from anywhere, and robots drawn per seed written as drawn.
nlohmann::json portable_scenario(const Scenario& scenario, const std::filesystem::path& dir);

// Whether a file name in a run folder is one of the run's records (scenario.json, final.json,
// trajectory.csv or trajectory.csv.gz, metrics.csv, map.csv, planner_map.csv, or a .partial
// file being written): a
// new run into the folder replaces these (and the figures: is_run_output in
// analysis/figures/figures.hpp), and keeps anything else.
bool is_record_file(const std::string& name);

// Throws ScenarioError naming the file (and line, for CSV) that is missing or malformed. The
// trajectory is read from trajectory.csv or trajectory.csv.gz, whichever the folder holds.
RunFiles read_run_files(const std::filesystem::path& dir);

}  // namespace covsim
