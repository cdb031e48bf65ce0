#include "planners/planner_registry.hpp"

#include "planners/grid_astar.hpp"
#include "planners/no_planner.hpp"
#include "planners/potential_field.hpp"
#include "planners/straight_line.hpp"
#include "planners/tangent_bug.hpp"
#include "planners/visibility_graph_planner.hpp"

namespace covsim {

Registry<PlannerEntry>& planner_registry() {
  static Registry<PlannerEntry> registry(
      "planner", {tangent_bug_entry(), potential_field_entry(), grid_astar_entry(),
                  visibility_graph_entry(), straight_line_entry(), no_planner_entry()});
  return registry;
}

PlannerSource planner_source(const PlannerConfig& config, const PlannerContext& context) {
  const PlannerEntry& e = planner_registry().at(config.type);
  return e.make(context, with_defaults(e.params, config.params));
}

std::unique_ptr<Planner> make_planner(std::string_view type, const Environment& env,
                                      const SensorSpec& sensor) {
  PlannerConfig c;
  c.type = std::string(type);
  return planner_source(c, PlannerContext{env, sensor})();
}

}  // namespace covsim
