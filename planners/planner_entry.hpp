#pragma once
// What a planner is to the rest of covsim: a registry entry (planner_registry()) with its
// name, description, parameter schema and factory. A factory is called once per run and
// returns a source that builds each robot's planner, so that what a planner type builds
// once (a visibility graph, an occupancy grid) is shared by the run's robots.
#include <cmath>
#include <functional>
#include <memory>

#include "core/registry.hpp"
#include "geometry/environment.hpp"
#include "planners/planner.hpp"

namespace covsim {

// What a planner should know about its sensor to set its thresholds.
struct SensorSpec {
  double noise_sigma = 0.0;  // metres of Gaussian range noise
  // Metres, on each axis: how much the robot's position estimate (so every wall it maps) may
  // jump from one step to the next (robots.localization).
  double position_sigma = 0.0;
  // Both together: how far a sensed wall point may wander between readings.
  double spread() const { return std::hypot(noise_sigma, position_sigma); }
};

struct PlannerContext {
  const Environment& environment;
  SensorSpec sensor;
  // A centralized run: the robots' planners share what they sense (one sensed map).
  bool shared_map = false;
};

// Builds one robot's planner.
using PlannerSource = std::function<std::unique_ptr<Planner>()>;

// One case of the planner contract suite (analysis/contract/planner_contract), as a bound sees it.
struct PathBoundCase {
  const Planner& planner;  // as it ended the case
  const Environment& environment;
  const Params& params;  // the planner's parameters in this case
  double shortest;       // L*: the shortest path to where it should end
  std::size_t turns;     // the reflex vertices L* turns at
  bool reachable;        // the goal lies in Ω
  double noise_sigma;    // the sensor's range noise
};

// What a planner promises, checked by the planner contract suite.
struct PlannerContract {
  // It reaches every goal in Ω and settles at a closest point of Ω to any other goal.
  bool complete = false;
  // The longest path it may take in a case; unset: no bound.
  std::function<double(const PathBoundCase&)> path_bound;
  // It never walks back over the ground it has just covered (geometry/reversals), but
  // once after it has gone round an obstacle (TangentBug's walk to the projection, the
  // shorter way round).
  bool keeps_direction = false;
  // Parameters for a course of the suite whose narrowest passage is `narrowest` metres (a
  // grid planner needs cells that fit); unset: its defaults.
  std::function<Params(double narrowest)> course_params;
};

struct PlannerEntry : ComponentInfo {
  std::function<PlannerSource(const PlannerContext&, const Params&)> make;
  // Optional: checks that need the environment (a grid too fine for it, say), run when a
  // scenario is loaded rather than when its run starts; throw ParamError.
  std::function<void(const Environment&, const Params&)> check;
  PlannerContract contract;
  // Its steps depend on the range sensor's range (a sensor-range study varies them).
  bool reads_range = false;
  // It plans from its sensor readings alone, never from its map of Ω: it works from an
  // estimated position (robots.localization), in the robot's odometry frame, and runs where
  // the robots do not know Ω. A planner on Ω's map works in Ω's frame from the estimate, on
  // the map inflated by its error (robot/belief_layer).
  bool senses_only = false;
  // It plans nothing, from Ω or its readings: straight at the goal, stopped where the body
  // meets a wall (straight_line, none). It needs no map, so it runs where the robots do not
  // know Ω (it meets the walls they have not mapped as it meets the others).
  bool blind = false;
  // It takes the walls of the readings its robot hears from neighbours (Planner::learn) when
  // robots that do not know Ω share their maps decentralized (a map planner on a sensed map
  // does, whatever this says).
  bool learns = false;
};

// A scenario's "planner": the type, and its parameters validated against its schema.
struct PlannerConfig {
  std::string type = "tangent_bug";
  Params params;
};

}  // namespace covsim
