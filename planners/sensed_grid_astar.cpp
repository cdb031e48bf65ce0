#include "planners/sensed_grid_astar.hpp"

#include "planners/grid_search.hpp"
#include "planners/shortcut.hpp"

namespace covsim {

std::optional<std::vector<Vec2>> SensedGridAStar::plan(Vec2 start, std::uint32_t from, Vec2 goal,
                                                       std::uint32_t to) {
  const SensedMap& m = planning_map();
  const GridSearch found = grid_search(
      m.shape(), [&m](std::int32_t i, std::int32_t j) { return m.free(i, j); }, from, to);
  if (found.cells.empty()) return std::nullopt;
  std::vector<Vec2> path{start};
  for (const std::uint32_t c : found.cells)
    path.push_back(m.center(c));
  path.push_back(goal);
  return shorten(path, [&m](Vec2 a, Vec2 b) { return m.clear(a, b); });
}

}  // namespace covsim
