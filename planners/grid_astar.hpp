#pragma once
// A map-based planner on an occupancy grid of Ω (see OccupancyGrid for the conservative
// blocking rule): 8-connected A* with the octile heuristic between the free cells nearest
// the start and the goal (no corner cutting), then the path is shortened by line of sight
// in Ω (each waypoint joined to the last of the following waypoints it sees). Replans when the goal
// changes. The grid is built once per environment and resolution and shared.
//
// Accuracy: the path keeps up to a cell diagonal away from walls and the grid's angles are
// multiples of 45° before shortening, so its length L satisfies L* <= L <= 1.0824 L* +
// 4 h (v + 1), where L* is the shortest path, h the resolution and v the number of reflex
// vertices L* turns at (1.0824 = 1 / cos 22.5°, the octile metric's worst stretch).
#include <memory>

#include "geometry/occupancy_grid.hpp"
#include "planners/map_planner.hpp"
#include "planners/planner_entry.hpp"

namespace covsim {

class GridAStar final : public MapPlanner {
 public:
  GridAStar(const Environment& env, std::shared_ptr<const OccupancyGrid> grid)
      : MapPlanner(env), grid_(std::move(grid)) {}
  std::string_view name() const override { return "grid_astar"; }

 private:
  std::optional<std::vector<Vec2>> plan(Vec2 start, Vec2 goal) override;
  std::shared_ptr<const OccupancyGrid> grid_;
};

// The worst-case path length the grid planner promises for a shortest path of length
// `shortest` turning at `turns` reflex vertices, on a grid of resolution h.
double grid_path_bound(double shortest, std::size_t turns, double h);

PlannerEntry grid_astar_entry();

}  // namespace covsim
