#include "planners/grid_astar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace covsim {

double grid_path_bound(double shortest, std::size_t turns, double h) {
  return 1.0824 * shortest + 4.0 * h * static_cast<double>(turns + 1);
}

namespace {
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

double octile(const OccupancyGrid& g, std::uint32_t a, std::uint32_t b) {
  const double dx = std::abs(g.column(a) - g.column(b)), dy = std::abs(g.row(a) - g.row(b));
  return g.resolution() * (std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy));
}

// Joins each kept waypoint to the last of the run of later waypoints it sees in Ω.
std::vector<Vec2> shorten(const Environment& env, const std::vector<Vec2>& path) {
  std::vector<Vec2> out{path.front()};
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t j = i + 1;
    while (j + 1 < path.size() && env.segment_inside(path[i], path[j + 1]))
      ++j;
    out.push_back(path[j]);
    i = j;
  }
  return out;
}
}  // namespace

std::optional<std::vector<Vec2>> GridAStar::plan(Vec2 start, Vec2 goal) {
  if (env_.segment_inside(start, goal)) return std::vector<Vec2>{start, goal};
  const OccupancyGrid& g = *grid_;
  const auto s = g.nearest_free(start), t = g.nearest_free(goal);
  if (!s || !t) return std::nullopt;
  struct Open {
    double f;
    std::uint32_t cell;
    bool operator>(const Open& o) const { return f > o.f || (f == o.f && cell > o.cell); }
  };
  std::priority_queue<Open, std::vector<Open>, std::greater<>> open;
  std::vector<double> cost(g.size(), std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> parent(g.size(), kNone);
  std::vector<std::uint8_t> closed(g.size(), 0);
  cost[*s] = 0.0;
  open.push({octile(g, *s, *t), *s});
  const double diagonal = std::sqrt(2.0) * g.resolution();
  while (!open.empty()) {
    const std::uint32_t c = open.top().cell;
    open.pop();
    if (closed[c] != 0) continue;
    closed[c] = 1;
    if (c == *t) break;
    const std::int32_t ci = g.column(c), cj = g.row(c);
    for (std::int32_t dj = -1; dj <= 1; ++dj) {
      for (std::int32_t di = -1; di <= 1; ++di) {
        if ((di == 0 && dj == 0) || !g.free(ci + di, cj + dj)) continue;
        // No corner cutting: a diagonal move needs both side cells free.
        if (di != 0 && dj != 0 && (!g.free(ci + di, cj) || !g.free(ci, cj + dj))) continue;
        const std::uint32_t n = g.index(ci + di, cj + dj);
        const double d = cost[c] + (di != 0 && dj != 0 ? diagonal : g.resolution());
        if (d < cost[n]) {
          cost[n] = d;
          parent[n] = c;
          open.push({d + octile(g, n, *t), n});
        }
      }
    }
  }
  if (closed[*t] == 0) return std::nullopt;
  std::vector<Vec2> path{goal};
  for (std::uint32_t c = *t; c != kNone; c = parent[c])
    path.push_back(g.center(c));
  path.push_back(start);
  std::reverse(path.begin(), path.end());
  return shorten(env_, path);
}

PlannerEntry grid_astar_entry() {
  PlannerEntry e;
  e.name = "grid_astar";
  e.description = "8-connected A* on an occupancy grid of the map, shortened by line of sight";
  const auto cell = [](const Environment& env) { return env.diameter() / 200.0; };
  e.params = {ParamSpec::number("resolution", "m", "the grid's cell side")
                  .greater_than(0)
                  .derived("1/200 of the diameter of Ω's bounding box",
                           [cell](const Environment& env) { return cell(env); })};
  const auto resolution = [cell](const Environment& env, const Params& p) {
    return p.maybe_number("resolution").value_or(cell(env));
  };
  e.check = [resolution](const Environment& env, const Params& p) {
    const double h = resolution(env, p);
    const Vec2 size = env.bounds().size();
    constexpr double kMaxCells = double(1 << 24);
    if (std::ceil(size.x / h) * std::ceil(size.y / h) > kMaxCells) {
      throw ParamError("resolution",
                       "resolution too fine for this environment: more than 16777216 cells");
    }
  };
  e.make = [resolution](const PlannerContext& ctx, const Params& p) -> PlannerSource {
    auto grid =
        std::make_shared<const OccupancyGrid>(ctx.environment, resolution(ctx.environment, p));
    const Environment* env = &ctx.environment;
    return [env, grid] { return std::make_unique<GridAStar>(*env, grid); };
  };
  e.contract.complete = true;  // for passages a few cells wide
  e.contract.path_bound = [resolution](const PathBoundCase& c) {
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
