#include "planners/visibility_graph_planner.hpp"

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
  e.make = [](const PlannerContext& ctx, const Params&) -> PlannerSource {
    auto graph = std::make_shared<const VisibilityGraph>(ctx.environment);
    return [graph] { return std::make_unique<VisibilityGraphPlanner>(graph); };
  };
  e.contract.complete = true;
  e.contract.path_bound = [](const PathBoundCase& c) { return c.shortest * (1.0 + 1e-9); };
  return e;
}

}  // namespace covsim
