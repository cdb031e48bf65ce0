#pragma once
// grid_astar on a sensed map (planner.map "sensed"): the same 8-connected A* (octile
// heuristic, no corner cutting) over the free cells of the robot's SensedMap, the path
// shortened by line of sight on that map; planned again from scratch when a reading shows
// that the rest of the path meets a wall (planners/sensed_map_planner).
#include "planners/sensed_map_planner.hpp"

namespace covsim {

class SensedGridAStar final : public SensedMapPlanner {
 public:
  SensedGridAStar(const Environment& env, std::shared_ptr<SensedMap> map)
      : SensedMapPlanner(env, std::move(map)) {}
  std::string_view name() const override { return "grid_astar"; }

 private:
  std::optional<std::vector<Vec2>> plan(Vec2 start, std::uint32_t from, Vec2 goal,
                                        std::uint32_t to) override;
};

}  // namespace covsim
