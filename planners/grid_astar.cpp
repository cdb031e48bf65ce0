#include "planners/grid_astar.hpp"

#include <cmath>

#include "planners/grid_search.hpp"
#include "planners/planner_map.hpp"
#include "planners/sensed_grid_astar.hpp"
#include "planners/shortcut.hpp"

namespace covsim {

double grid_path_bound(double shortest, std::size_t turns, double h) {
  return 1.0824 * shortest + 4.0 * h * static_cast<double>(turns + 1);
}

std::optional<std::vector<Vec2>> GridAStar::plan(Vec2 start, Vec2 goal) {
  if (env_.segment_inside(start, goal)) return std::vector<Vec2>{start, goal};
  const OccupancyGrid& g = *grid_;
  const auto s = g.nearest_free(start), t = g.nearest_free(goal);
  if (!s || !t) return std::nullopt;
  const GridSearch found = grid_search(
      GridShape{g.nx(), g.ny(), g.resolution()},
      [&g](std::int32_t i, std::int32_t j) { return g.free(i, j); }, *s, *t);
  if (found.cells.empty()) return std::nullopt;
  std::vector<Vec2> path{start};
  for (const std::uint32_t c : found.cells)
    path.push_back(g.center(c));
  path.push_back(goal);
  return shorten(path, [this](Vec2 a, Vec2 b) { return env_.segment_inside(a, b); });
}

PlannerEntry grid_astar_entry() {
  PlannerEntry e;
  e.name = "grid_astar";
  e.description = "8-connected A* on an occupancy grid of the map, shortened by line of sight";
  const auto cell = [](const Environment& env) { return env.diameter() / 200.0; };
  e.params = {ParamSpec::number("resolution", "m", "the grid's cell side")
                  .greater_than(0)
                  .derived("1/200 of the diameter of Ω's bounding box",
                           [cell](const Environment& env) { return cell(env); }),
              planner_map_param()};
  const auto resolution = [cell](const Environment& env, const Params& p) {
    return p.maybe_number("resolution").value_or(cell(env));
  };
  e.check = [resolution](const Environment& env, const Params& p) {
    check_grid_resolution(env, resolution(env, p));
  };
  e.make = [resolution](const PlannerContext& ctx, const Params& p) -> PlannerSource {
    const Environment* env = &ctx.environment;
    if (plans_on_sensed_map(p)) {
      const double h = resolution(*env, p);
      const SensorSpec sensor = ctx.sensor;
      auto shared = ctx.shared_map ? sensed_map_for(*env, h, sensor) : nullptr;
      return [env, h, sensor, shared] {
        return std::make_unique<SensedGridAStar>(*env,
                                                 shared ? shared : sensed_map_for(*env, h, sensor));
      };
    }
    auto grid =
        std::make_shared<const OccupancyGrid>(ctx.environment, resolution(ctx.environment, p));
    return [env, grid] { return std::make_unique<GridAStar>(*env, grid); };
  };
  e.contract.complete = true;  // for passages a few cells wide
  e.contract.path_bound = [resolution](const PathBoundCase& c) {
    // On a sensed map the way depends on what comes into view: no bound but the step limit.
    if (plans_on_sensed_map(c.params)) return double(INFINITY);
    return grid_path_bound(c.shortest, c.turns, resolution(c.environment, c.params));
  };
  e.contract.course_params = [](double narrowest) {
    Params p;
    p.set("resolution", narrowest / 4.0);  // every passage holds connected free cells
    return p;
  };
  return e;
}

}  // namespace covsim
