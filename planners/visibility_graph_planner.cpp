#include "planners/visibility_graph_planner.hpp"

#include "planners/planner_map.hpp"
#include "planners/sensed_visibility_graph.hpp"

namespace covsim {

std::optional<std::vector<Vec2>> VisibilityGraphPlanner::plan(Vec2 start, Vec2 goal) {
  GeodesicPath p = graph_->shortest_path(start, goal);
  if (!p.found()) return std::nullopt;
  return std::move(p.points);
}

PlannerEntry visibility_graph_entry() {
  PlannerEntry e;
  e.name = "visibility_graph";
  e.description = "exact shortest paths in Ω: A* on the visibility graph of its reflex vertices";
  e.params = {planner_map_param(),
              ParamSpec::number("resolution", "m",
                                "the cells of the sensed map, whose wall cells it plans round "
                                "(planner.map \"sensed\" only)")
                  .greater_than(0)
                  .derived("1/200 of the diameter of Ω's bounding box")};
  const auto resolution = [](const Environment& env, const Params& p) {
    return p.maybe_number("resolution").value_or(env.diameter() / 200.0);
  };
  e.check = [](const Environment& env, const Params& p) {
    if (p.has("resolution") && !plans_on_sensed_map(p))
      throw ParamError("resolution",
                       "applies to the sensed map only: on the given map the graph is exact "
                       "(set planner.map to \"sensed\", or leave resolution out)");
    check_grid_resolution(env, p.maybe_number("resolution").value_or(env.diameter() / 200.0));
  };
  e.make = [resolution](const PlannerContext& ctx, const Params& p) -> PlannerSource {
    if (plans_on_sensed_map(p)) {
      const Environment* env = &ctx.environment;
      const double h = resolution(*env, p);
      const SensorSpec sensor = ctx.sensor;
      auto shared = ctx.shared_map ? sensed_map_for(*env, h, sensor) : nullptr;
      return [env, h, sensor, shared] {
        return std::make_unique<SensedVisibilityGraph>(
            *env, shared ? shared : sensed_map_for(*env, h, sensor));
      };
    }
    auto graph = std::make_shared<const VisibilityGraph>(ctx.environment);
    return [graph] { return std::make_unique<VisibilityGraphPlanner>(graph); };
  };
  e.contract.complete = true;
  e.contract.path_bound = [](const PathBoundCase& c) {
    // On a sensed map the way depends on what comes into view: no bound but the step limit.
    return plans_on_sensed_map(c.params) ? double(INFINITY) : c.shortest * (1.0 + 1e-9);
  };
  e.contract.course_params = [](double narrowest) {
    Params p;
    p.set("resolution", narrowest / 4.0);  // the sensed map's cells (given: unused)
    return p;
  };
  return e;
}

}  // namespace covsim
