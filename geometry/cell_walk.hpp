#pragma once
// The square cells of a grid that a closed segment meets, for maps kept on cells (a sensed
// map's wall cells, an occupancy grid's hits).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/vec2.hpp"

namespace covsim {

// Calls f(i, j) for the cells of the grid with cell (0, 0) at [origin, origin + h)² that the
// closed segment a -> b meets (outside any bounds too), until f returns false; whether it
// never did. Column by column, the rows the segment's stretch over that column spans; a
// segment on a cell line meets the cells on both sides (closed squares).
template <class F>
bool for_each_cell_on(Vec2 origin, double h, Vec2 a, Vec2 b, F&& f) {
  const Vec2 u = (a - origin) / h, v = (b - origin) / h;
  const double x0 = std::min(u.x, v.x), x1 = std::max(u.x, v.x);
  auto i0 = static_cast<std::int32_t>(std::floor(x0));
  if (static_cast<double>(i0) == x0) --i0;
  const auto i1 = static_cast<std::int32_t>(std::floor(x1));
  const auto rows = [&](double y0, double y1, std::int32_t i) {
    const double lo = std::min(y0, y1);
    auto j0 = static_cast<std::int32_t>(std::floor(lo));
    if (static_cast<double>(j0) == lo) --j0;
    const auto j1 = static_cast<std::int32_t>(std::floor(std::max(y0, y1)));
    for (std::int32_t j = j0; j <= j1; ++j)
      if (!f(i, j)) return false;
    return true;
  };
  for (std::int32_t i = i0; i <= i1; ++i) {
    if (u.x == v.x) {
      if (!rows(u.y, v.y, i)) return false;
      continue;
    }
    const double xa = std::max(x0, static_cast<double>(i)),
                 xb = std::min(x1, static_cast<double>(i + 1));
    const auto y_at = [&](double x) { return u.y + (v.y - u.y) * ((x - u.x) / (v.x - u.x)); };
    if (!rows(y_at(xa), y_at(xb), i)) return false;
  }
  return true;
}

}  // namespace covsim
