#pragma once
// A* on a grid of square cells, 8-connected with the octile heuristic and no corner cutting
// (a diagonal move needs both side cells free), for the grid planners on the given map
// (geometry/occupancy_grid) and on a sensed one (planners/sensed_map). Ties go to the lower
// cell index, so a search depends on the grid alone.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <queue>
#include <vector>

namespace covsim {

struct GridShape {
  std::int32_t nx = 0, ny = 0;
  double resolution = 1.0;
  std::uint32_t index(std::int32_t i, std::int32_t j) const {
    return static_cast<std::uint32_t>(j * nx + i);
  }
  std::int32_t column(std::uint32_t c) const { return static_cast<std::int32_t>(c) % nx; }
  std::int32_t row(std::uint32_t c) const { return static_cast<std::int32_t>(c) / nx; }
  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
};

// Calls f(n, diagonal) for each cell n one move from c: the 8 neighbours where free(i, j)
// holds, a diagonal one only when both side cells are free too (no corner cutting).
template <class Free, class F>
void for_each_move(const GridShape& g, const Free& free, std::uint32_t c, F&& f) {
  const std::int32_t ci = g.column(c), cj = g.row(c);
  for (std::int32_t dj = -1; dj <= 1; ++dj) {
    for (std::int32_t di = -1; di <= 1; ++di) {
      if ((di == 0 && dj == 0) || !free(ci + di, cj + dj)) continue;
      if (di != 0 && dj != 0 && (!free(ci + di, cj) || !free(ci, cj + dj))) continue;
      f(g.index(ci + di, cj + dj), di != 0 && dj != 0);
    }
  }
}

struct GridSearch {
  std::vector<std::uint32_t> cells;  // s to t; empty if t was not reached
  std::vector<std::uint8_t> closed;  // the cells the search settled (all reachable ones if
                                     // t was not reached)
};

// From cell s to cell t over the cells where free(i, j) holds.
template <class Free>
GridSearch grid_search(const GridShape& g, const Free& free, std::uint32_t s, std::uint32_t t) {
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  const auto octile = [&](std::uint32_t a, std::uint32_t b) {
    const double dx = std::abs(g.column(a) - g.column(b)), dy = std::abs(g.row(a) - g.row(b));
    return g.resolution * (std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy));
  };
  struct Open {
    double f;
    std::uint32_t cell;
    bool operator>(const Open& o) const { return f > o.f || (f == o.f && cell > o.cell); }
  };
  std::priority_queue<Open, std::vector<Open>, std::greater<>> open;
  std::vector<double> cost(g.size(), std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> parent(g.size(), kNone);
  GridSearch out;
  out.closed.assign(g.size(), 0);
  cost[s] = 0.0;
  open.push({octile(s, t), s});
  const double diagonal = std::sqrt(2.0) * g.resolution;
  while (!open.empty()) {
    const std::uint32_t c = open.top().cell;
    open.pop();
    if (out.closed[c] != 0) continue;
    out.closed[c] = 1;
    if (c == t) break;
    for_each_move(g, free, c, [&](std::uint32_t n, bool diagonal_move) {
      const double d = cost[c] + (diagonal_move ? diagonal : g.resolution);
      if (d < cost[n]) {
        cost[n] = d;
        parent[n] = c;
        open.push({d + octile(n, t), n});
      }
    });
  }
  if (out.closed[t] == 0) return out;
  for (std::uint32_t c = t; c != kNone; c = parent[c])
    out.cells.push_back(c);
  std::reverse(out.cells.begin(), out.cells.end());
  return out;
}

// The cells reachable from s over the free ones, with the search's moves (per cell: 1 if
// reachable).
template <class Free>
std::vector<std::uint8_t> grid_reach(const GridShape& g, const Free& free, std::uint32_t s) {
  std::vector<std::uint8_t> seen(g.size(), 0);
  std::vector<std::uint32_t> todo{s};
  seen[s] = 1;
  while (!todo.empty()) {
    const std::uint32_t c = todo.back();
    todo.pop_back();
    for_each_move(g, free, c, [&](std::uint32_t n, bool) {
      if (seen[n] != 0) return;
      seen[n] = 1;
      todo.push_back(n);
    });
  }
  return seen;
}

}  // namespace covsim
