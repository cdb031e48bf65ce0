#pragma once
// Planners by name, with parameters scaled to the environment they will run in. One factory
// serves all the robots of a run: the maps that map-based planners need (the visibility
// graph, the occupancy grid) are built once, on first use, and shared.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/occupancy_grid.hpp"
#include "core/geometry/visibility_graph.hpp"
#include "planners/planner.hpp"

namespace covsim {

// The names the factory accepts.
const std::vector<std::string_view>& planner_names();

// A scenario's "planner" object. Unset parameters take the planner's defaults for the
// environment.
struct PlannerConfig {
  std::string type = "tangent_bug";
  std::optional<double> influence;          // potential_field: d0, metres
  std::optional<double> repulsive_gain;     // potential_field
  std::optional<std::size_t> stall_window;  // potential_field: steps
  std::optional<double> resolution;         // grid_astar: cell side, metres
  // grid_astar's default cell side: 1/200 of Ω's bounding-box diameter.
  static double default_resolution(const Environment& env) { return env.diameter() / 200.0; }
};

// What a planner should know about its sensor to set its thresholds.
struct SensorSpec {
  double noise_sigma = 0.0;  // metres of Gaussian range noise
};

class PlannerFactory {
 public:
  // Throws std::invalid_argument for an unknown planner type.
  PlannerFactory(const Environment& env, PlannerConfig config, SensorSpec sensor = {});
  std::unique_ptr<Planner> make();
  const PlannerConfig& config() const { return config_; }

 private:
  const Environment& env_;
  PlannerConfig config_;
  SensorSpec sensor_;
  std::shared_ptr<const VisibilityGraph> graph_;
  std::shared_ptr<const OccupancyGrid> grid_;
};

// One planner of the given type with default parameters (throws for an unknown name).
std::unique_ptr<Planner> make_planner(std::string_view name, const Environment& env,
                                      const SensorSpec& sensor = {});

}  // namespace covsim
