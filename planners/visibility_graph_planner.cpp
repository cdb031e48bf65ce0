#include "planners/visibility_graph_planner.hpp"

namespace covsim {

std::optional<std::vector<Vec2>> VisibilityGraphPlanner::plan(Vec2 start, Vec2 goal) {
  GeodesicPath p = graph_->shortest_path(start, goal);
  if (!p.found()) return std::nullopt;
  return std::move(p.points);
}

}  // namespace covsim
