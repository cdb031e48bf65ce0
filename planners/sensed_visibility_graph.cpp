#include "planners/sensed_visibility_graph.hpp"

#include <algorithm>
#include <limits>
#include <queue>

namespace covsim {

std::optional<std::vector<Vec2>> SensedVisibilityGraph::plan(Vec2 start, std::uint32_t from,
                                                             Vec2 goal, std::uint32_t to) {
  const SensedMap& m = planning_map();
  if (corners_map_ != &m || corners_version_ != m.version()) {
    corners_.clear();
    for (std::int32_t j = 0; j < m.ny(); ++j) {
      for (std::int32_t i = 0; i < m.nx(); ++i) {
        if (!m.free(i, j)) continue;
        bool corner = false;
        for (const std::int32_t dj : {-1, 1})
          for (const std::int32_t di : {-1, 1})
            corner = corner || (!m.free(i + di, j + dj) && m.free(i + di, j) && m.free(i, j + dj));
        if (corner) corners_.push_back(m.index(i, j));
      }
    }
    corners_map_ = &m;
    corners_version_ = m.version();
  }
  // Nodes: the start, the goal, the cells they enter by, the corners.
  std::vector<Vec2> node{start, goal, m.center(from), m.center(to)};
  for (const std::uint32_t c : corners_)
    if (c != from && c != to) node.push_back(m.center(c));
  const std::size_t n = node.size();
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<double> cost(n, INFINITY);
  std::vector<std::size_t> parent(n, kNone);
  std::vector<std::uint8_t> closed(n, 0);
  struct Open {
    double f;
    std::size_t node;
    bool operator>(const Open& o) const { return f > o.f || (f == o.f && node > o.node); }
  };
  std::priority_queue<Open, std::vector<Open>, std::greater<>> open;
  cost[0] = 0.0;
  open.push({distance(start, goal), 0});
  while (!open.empty()) {
    const std::size_t u = open.top().node;
    open.pop();
    if (closed[u] != 0) continue;
    closed[u] = 1;
    if (u == 1) break;
    for (std::size_t v = 1; v < n; ++v) {
      if (closed[v] != 0) continue;
      const double d = cost[u] + distance(node[u], node[v]);
      if (!(d < cost[v]) || !m.clear(node[u], node[v])) continue;
      cost[v] = d;
      parent[v] = u;
      open.push({d + distance(node[v], goal), v});
    }
  }
  if (closed[1] == 0) return std::nullopt;
  std::vector<Vec2> path;
  for (std::size_t u = 1; u != kNone; u = parent[u])
    path.push_back(node[u]);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace covsim
