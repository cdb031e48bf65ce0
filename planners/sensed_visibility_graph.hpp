#pragma once
// visibility_graph on a sensed map (planner.map "sensed"): shortest paths on the visibility
// graph of the believed obstacles, the wall cells of the robot's SensedMap. Its nodes are the
// free cells off the wall cells' convex corners (a free cell with a wall cell diagonal to it
// and both cells between them free), with the start, the goal and the cells they enter the
// grid by; its edges the clear legs between them (SensedMap::clear), found as the A* search
// (straight-line heuristic) reaches each node. On the given map the graph is exact and its
// paths graze Ω's corners; here they keep half a cell off the walls seen, like grid_astar's,
// and are planned again from scratch when a reading shows that the rest meets a wall
// (planners/sensed_map_planner).
#include <cstdint>

#include "planners/sensed_map_planner.hpp"

namespace covsim {

class SensedVisibilityGraph final : public SensedMapPlanner {
 public:
  SensedVisibilityGraph(const Environment& env, std::shared_ptr<SensedMap> map)
      : SensedMapPlanner(env, std::move(map)) {}
  std::string_view name() const override { return "visibility_graph"; }

 private:
  std::optional<std::vector<Vec2>> plan(Vec2 start, std::uint32_t from, Vec2 goal,
                                        std::uint32_t to) override;
  // The corner cells, for the map `corners_map_` as it was at its version `corners_version_`.
  std::vector<std::uint32_t> corners_;
  const SensedMap* corners_map_ = nullptr;
  std::uint64_t corners_version_ = UINT64_MAX;
};

}  // namespace covsim
