#pragma once
// The optimal reference: the exact shortest path in Ω, on the visibility graph of Ω's
// reflex vertices (one graph per environment, shared by every robot's planner).
#include <memory>

#include "geometry/visibility_graph.hpp"
#include "planners/map_planner.hpp"
#include "planners/planner_entry.hpp"

namespace covsim {

class VisibilityGraphPlanner final : public MapPlanner {
 public:
  explicit VisibilityGraphPlanner(std::shared_ptr<const VisibilityGraph> graph)
      : MapPlanner(graph->environment()), graph_(std::move(graph)) {}
  std::string_view name() const override { return "visibility_graph"; }

 private:
  std::optional<std::vector<Vec2>> plan(Vec2 start, Vec2 goal) override;
  std::shared_ptr<const VisibilityGraph> graph_;
};

PlannerEntry visibility_graph_entry();

}  // namespace covsim
