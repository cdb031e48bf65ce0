#include "planners/planner_factory.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "planners/grid_astar.hpp"
#include "planners/potential_field.hpp"
#include "planners/straight_line.hpp"
#include "planners/tangent_bug.hpp"
#include "planners/visibility_graph_planner.hpp"

namespace covsim {

const std::vector<std::string_view>& planner_names() {
  static const std::vector<std::string_view> names{"tangent_bug", "potential_field", "grid_astar",
                                                   "visibility_graph", "straight_line"};
  return names;
}

PlannerFactory::PlannerFactory(const Environment& env, PlannerConfig config, SensorSpec sensor)
    : env_(env), config_(std::move(config)), sensor_(sensor) {
  const auto& names = planner_names();
  if (std::find(names.begin(), names.end(), config_.type) == names.end())
    throw std::invalid_argument("unknown planner \"" + config_.type + "\"");
}

std::unique_ptr<Planner> PlannerFactory::make() {
  const std::string& t = config_.type;
  if (t == "tangent_bug") {
    double boundary = 0.0;
    for (const BoundaryEdge& e : env_.boundary())
      boundary += distance(e.a, e.b);
    TangentBugParams p = TangentBugParams::for_environment(env_.diameter(), boundary);
    // A decrease smaller than the sensor's noise is no progress: three standard deviations.
    p.progress = std::max(p.progress, 3.0 * sensor_.noise_sigma);
    p.noise_margin = 3.0 * sensor_.noise_sigma;
    return std::make_unique<TangentBug>(p);
  }
  if (t == "potential_field") {
    PotentialFieldParams p = PotentialFieldParams::for_environment(env_.diameter());
    if (config_.influence) p.influence = *config_.influence;
    if (config_.repulsive_gain) p.repulsive_gain = *config_.repulsive_gain;
    if (config_.stall_window) p.stall_window = *config_.stall_window;
    p.progress = std::max(p.progress, 3.0 * sensor_.noise_sigma);
    return std::make_unique<PotentialField>(env_, p);
  }
  if (t == "grid_astar") {
    if (!grid_) {
      grid_ = std::make_shared<OccupancyGrid>(
          env_, config_.resolution.value_or(PlannerConfig::default_resolution(env_)));
    }
    return std::make_unique<GridAStar>(env_, grid_);
  }
  if (t == "visibility_graph") {
    if (!graph_) graph_ = std::make_shared<VisibilityGraph>(env_);
    return std::make_unique<VisibilityGraphPlanner>(graph_);
  }
  return std::make_unique<StraightLine>(env_);
}

std::unique_ptr<Planner> make_planner(std::string_view name, const Environment& env,
                                      const SensorSpec& sensor) {
  PlannerConfig c;
  c.type = std::string(name);
  return PlannerFactory(env, c, sensor).make();
}

}  // namespace covsim
