#pragma once
// One run of the paper's controller on a scenario, from start to convergence (or the time
// limit), and what it ends with: the final positions, the three costs of the paper's
// Remark 1, and the fingerprint.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "robot/coverage_controller.hpp"
#include "scenarios/scenario.hpp"

namespace covsim {

class TraceSink;

struct RobotOutcome {
  Vec2 position, virtual_generator, virtual_target, real_target;
  bool projected = false;
  PlanStatus status = PlanStatus::reached;
  double path_length = 0.0;
  // Failure measures: loop-2 steps with the loop-1 target outside Ω, seconds stalled, and
  // the final distance from the centroid of its cell in the last partition.
  std::uint64_t target_outside_steps = 0;
  double stalled_time = 0.0;
  double centroid_distance = 0.0;
};

struct CoverageOutcome {
  std::string scenario;  // the scenario's source (its file name)
  bool converged = false;
  SimTime sim_time;
  // "converged", "planner_failure" (see PlannerFailure), "left_environment" (see
  // LeftEnvironment), "stuck" (see CoverageController::stuck) or "max_time".
  std::string stop_reason;
  std::optional<PlannerFailure> planner_failure;
  std::optional<LeftEnvironment> left_environment;
  std::uint64_t events = 0;
  std::uint64_t seed = 0;
  std::uint64_t fingerprint = 0;
  std::vector<RobotOutcome> robots;
  // Remark 1: H of the virtual generators on their partition, of the real positions on
  // theirs (the last partition), and of the real positions on the virtual partition.
  double cost_virtual = 0.0, cost_real = 0.0, cost_real_in_virtual_partition = 0.0;
  bool decentralized = false;  // false: the ideal network, every robot knows every state
  NetworkTotals network;
  // Convergence measures: the time from which the real cost stays within 10%, 5% and 1% of
  // its final value (sampled every metrics period), and the robots' total path length.
  double time_to_10_percent = 0.0, time_to_5_percent = 0.0, time_to_1_percent = 0.0;
  // The final real cost over the least one sampled during the run (1: it ended at its best;
  // above 1, the last moves undid part of what was won; unknown for a run read from a
  // folder written before it was measured).
  double cost_to_best = NAN;
  double path_length = 0.0;
  // Sums and means of the robots' failure measures.
  std::uint64_t target_outside_steps = 0;
  double stalled_time = 0.0;
  double centroid_distance_mean = 0.0, centroid_distance_max = 0.0;
  // Bodies (CoverageController::body_gap_min and the rest): NaN and zeros for points.
  double radius = 0.0;
  double body_gap_min = NAN;
  double contact_time = 0.0;
  std::uint64_t wall_contacts = 0;
  // Collision avoidance (CoverageController::deadlocks and the rest): zeros without it.
  std::uint64_t deadlocks = 0, deadlocks_resolved = 0;
  double deadlock_time = 0.0;
  // Kinematics (CoverageController::turn_time, hard_stops): zeros for the single integrator.
  double turn_time = 0.0;
  std::uint64_t hard_stops = 0;
  // Localization (CoverageController::localization_error_mean and the rest): zeros when exact.
  double localization_error_mean = 0.0, localization_error_max = 0.0;
  std::uint64_t fixes = 0;
  // Mapping (robot/mapping.hpp): what the robots knew of Ω beforehand, and, when they did not
  // know it, the fraction of Ω's free area known at the end (merged and the least-informed
  // robot's), when the merged map reached 90% and 100% of it (NaN: never), the disagreement
  // between robots' maps, map bytes broadcast, readings kept, obstacles (holes and pockets)
  // and how many the least-informed robot knew, goals found unreachable while the robot's map
  // placed them in free space (CoverageController::discoveries), and the final real cost with Ω
  // known (NaN: not compared).
  std::string known = "full";
  double known_fraction = 1.0, known_fraction_min = 1.0;
  double mapping_time_90 = 0.0, mapping_time_100 = 0.0;
  double map_disagreement = 0.0;
  std::uint64_t map_bytes = 0, map_bytes_new = 0, scans = 0, obstacles = 0, obstacles_known_min = 0,
                discoveries = 0;
  double cost_known = NAN;
  // The map: "polygons" or "occupancy"; with the occupancy grid, the mean over the robots'
  // maps of the fractions of cells wrong either way (Mapping::errors; NaN with polygons).
  std::string map_model;
  double map_false_occupied = NAN, map_false_free = NAN;
  double cost_ratio() const { return cost_real / cost_known; }
  // loops.loop1_period / loops.loop2_period; NaN for the classic schedule.
  double loop_ratio = NAN;
  // Wall-clock seconds spent in planner steps, and how many steps: the only measures besides
  // wall times that vary between runs.
  double planner_seconds = 0.0;
  std::uint64_t planner_steps = 0;
  // What built the covsim that ran it (sim/provenance.hpp).
  nlohmann::ordered_json provenance;
  // Mean wall-clock microseconds per planner step (0 without steps).
  double planner_step_time_us() const {
    return planner_steps > 0 ? 1e6 * planner_seconds / static_cast<double>(planner_steps) : 0.0;
  }
};

// The first sample time from which every later value stays within (1 + fraction) of the last
// value: how long a cost series took to settle. 0 for an empty series.
double settling_time(const std::vector<std::pair<double, double>>& series, double fraction);
// `last` over the least of it and the series' values (1 for an empty series).
double ratio_to_best(const std::vector<std::pair<double, double>>& series, double last);

// Throws ScenarioError if the scenario has no robots or no seed.
// make_planner, if given, builds each robot's planner instead of the scenario's.
CoverageOutcome run_coverage(const Scenario& scenario, CoverageObserver* observer = nullptr,
                             TraceSink* trace = nullptr, const PlannerMaker& make_planner = {});

}  // namespace covsim
