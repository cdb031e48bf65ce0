#include "geometry/cell_region.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

#include "geometry/geometry_error.hpp"

namespace covsim {

std::uint32_t CellGrid::cell_of(Vec2 p) const {
  const auto clamp = [](double v, std::int32_t n) {
    const double f = std::floor(v);
    if (!(f >= 0.0)) return 0;
    return static_cast<std::int32_t>(std::min(f, static_cast<double>(n - 1)));
  };
  return index(clamp((p.x - origin.x) / cell, nx), clamp((p.y - origin.y) / cell, ny));
}

namespace {

// The cells of `open` 4-connected to the start cells, 1 where reached.
std::vector<std::uint8_t> flood(const CellGrid& g, const std::vector<std::uint8_t>& open,
                                const std::vector<std::uint32_t>& starts) {
  std::vector<std::uint8_t> in(g.size(), 0);
  std::deque<std::uint32_t> queue;
  for (const std::uint32_t c : starts)
    if (open[c] != 0 && in[c] == 0) in[c] = 1, queue.push_back(c);
  while (!queue.empty()) {
    const std::uint32_t c = queue.front();
    queue.pop_front();
    const std::int32_t i = static_cast<std::int32_t>(c) % g.nx,
                       j = static_cast<std::int32_t>(c) / g.nx;
    const std::int32_t di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const std::int32_t u = i + di[k], v = j + dj[k];
      if (u < 0 || v < 0 || u >= g.nx || v >= g.ny) continue;
      const std::uint32_t n = g.index(u, v);
      if (open[n] != 0 && in[n] == 0) in[n] = 1, queue.push_back(n);
    }
  }
  return in;
}

// The nearest open cell to cell c, ring by ring (within `rings`); c itself if none.
std::uint32_t nearest_open(const CellGrid& g, const std::vector<std::uint8_t>& open,
                           std::uint32_t c, std::int32_t rings) {
  if (open[c] != 0) return c;
  const std::int32_t i = static_cast<std::int32_t>(c) % g.nx,
                     j = static_cast<std::int32_t>(c) / g.nx;
  for (std::int32_t r = 1; r <= rings; ++r) {
    std::int64_t best = -1;
    std::int64_t least = INT64_MAX;
    for (std::int32_t v = j - r; v <= j + r; ++v)
      for (std::int32_t u = i - r; u <= i + r; ++u) {
        if (std::max(std::abs(u - i), std::abs(v - j)) != r) continue;
        if (u < 0 || v < 0 || u >= g.nx || v >= g.ny || open[g.index(u, v)] == 0) continue;
        const std::int64_t d = std::int64_t{u - i} * (u - i) + std::int64_t{v - j} * (v - j);
        if (d < least) least = d, best = g.index(u, v);
      }
    if (best >= 0) return static_cast<std::uint32_t>(best);
  }
  return c;
}

bool in_region(const CellGrid& g, const std::vector<std::uint8_t>& r, std::int32_t i,
               std::int32_t j) {
  return i >= 0 && j >= 0 && i < g.nx && j < g.ny && r[g.index(i, j)] != 0;
}

}  // namespace

std::vector<std::uint8_t> seeded_region(const CellGrid& g, const std::vector<std::uint8_t>& open,
                                        const std::vector<Vec2>& seeds) {
  std::vector<std::uint32_t> starts;
  for (const Vec2 p : seeds)
    starts.push_back(nearest_open(g, open, g.cell_of(p), 8));
  std::vector<std::uint8_t> allowed = open;
  for (;;) {
    std::vector<std::uint8_t> region = flood(g, allowed, starts);
    // Corners where two cells of the region meet diagonally, the other two outside.
    bool pinched = false;
    for (std::int32_t j = 1; j < g.ny; ++j)
      for (std::int32_t i = 1; i < g.nx; ++i) {
        const bool a = in_region(g, region, i - 1, j - 1), b = in_region(g, region, i, j - 1),
                   c = in_region(g, region, i - 1, j), d = in_region(g, region, i, j);
        if (a && d && !b && !c)
          allowed[g.index(i, j)] = 0, region[g.index(i, j)] = 0, pinched = true;
        if (b && c && !a && !d)
          allowed[g.index(i - 1, j)] = 0, region[g.index(i - 1, j)] = 0, pinched = true;
      }
    if (!pinched) return region;
  }
}

namespace {

// The region's 4-connected parts: a label per cell (0: outside) and each label's size.
std::vector<std::size_t> label_parts(const CellGrid& g, const std::vector<std::uint8_t>& region,
                                     std::vector<std::uint32_t>& label) {
  label.assign(g.size(), 0);
  std::vector<std::size_t> sizes{0};
  for (std::uint32_t c = 0; c < g.size(); ++c) {
    if (region[c] == 0 || label[c] != 0) continue;
    const auto next = static_cast<std::uint32_t>(sizes.size());
    const std::vector<std::uint8_t> part = flood(g, region, {c});
    std::size_t size = 0;
    for (std::uint32_t k = 0; k < g.size(); ++k)
      if (part[k] != 0) label[k] = next, ++size;
    sizes.push_back(size);
  }
  return sizes;
}

std::unique_ptr<Environment> trace(const CellGrid& g, const std::vector<std::uint32_t>& label,
                                   std::uint32_t best_label);

}  // namespace

std::unique_ptr<Environment> region_environment(const CellGrid& g,
                                                const std::vector<std::uint8_t>& region) {
  // The largest 4-connected part (the first in row order among equals).
  std::vector<std::uint32_t> label;
  const std::vector<std::size_t> sizes = label_parts(g, region, label);
  std::uint32_t best_label = 0;
  for (std::uint32_t k = 1; k < sizes.size(); ++k)
    if (sizes[k] > sizes[best_label]) best_label = k;
  if (best_label == 0) throw GeometryError("a region of cells needs at least one cell");
  return trace(g, label, best_label);
}

std::vector<std::unique_ptr<const Environment>> eroded_parts(
    const CellGrid& g, const std::vector<std::uint8_t>& region, double radius) {
  // A cell goes when a cell outside lies nearer than the radius, square to square.
  std::vector<std::uint8_t> kept = region;
  const auto reach = static_cast<std::int32_t>(std::ceil(radius / g.cell)) + 1;
  const auto outside = [&](std::int32_t i, std::int32_t j) {
    return i < 0 || j < 0 || i >= g.nx || j >= g.ny || region[g.index(i, j)] == 0;
  };
  for (std::int32_t j = -1; j <= g.ny; ++j)
    for (std::int32_t i = -1; i <= g.nx; ++i) {
      if (!outside(i, j)) continue;
      for (std::int32_t v = std::max(0, j - reach); v <= std::min(g.ny - 1, j + reach); ++v)
        for (std::int32_t u = std::max(0, i - reach); u <= std::min(g.nx - 1, i + reach); ++u) {
          const double dx = std::max(0, std::abs(u - i) - 1) * g.cell,
                       dy = std::max(0, std::abs(v - j) - 1) * g.cell;
          if (dx * dx + dy * dy < radius * radius) kept[g.index(u, v)] = 0;
        }
    }
  // Every kept cell seeds: all parts stay, parted where they meet at a corner.
  std::vector<Vec2> seeds;
  for (std::int32_t j = 0; j < g.ny; ++j)
    for (std::int32_t i = 0; i < g.nx; ++i)
      if (kept[g.index(i, j)] != 0)
        seeds.push_back({g.origin.x + (i + 0.5) * g.cell, g.origin.y + (j + 0.5) * g.cell});
  std::vector<std::unique_ptr<const Environment>> out;
  if (seeds.empty()) return out;
  const std::vector<std::uint8_t> parted = seeded_region(g, kept, seeds);
  std::vector<std::uint32_t> label;
  const std::vector<std::size_t> sizes = label_parts(g, parted, label);
  std::vector<std::uint32_t> order;
  for (std::uint32_t k = 1; k < sizes.size(); ++k)
    order.push_back(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return sizes[a] > sizes[b]; });
  for (const std::uint32_t k : order)
    out.push_back(trace(g, label, k));
  return out;
}

namespace {

std::unique_ptr<Environment> trace(const CellGrid& g, const std::vector<std::uint32_t>& label,
                                   std::uint32_t best_label) {
  const auto in = [&](std::int32_t i, std::int32_t j) {
    return i >= 0 && j >= 0 && i < g.nx && j < g.ny && label[g.index(i, j)] == best_label;
  };
  // Each side of a cell with the outside beyond, directed with the region on its left, from
  // grid corner to grid corner; without pinches every corner starts at most one.
  const std::int64_t stride = g.nx + 1;
  std::map<std::int64_t, std::int64_t> next;
  const auto corner = [&](std::int32_t i, std::int32_t j) { return std::int64_t{j} * stride + i; };
  for (std::int32_t j = 0; j < g.ny; ++j)
    for (std::int32_t i = 0; i < g.nx; ++i) {
      if (!in(i, j)) continue;
      if (!in(i, j - 1)) next[corner(i, j)] = corner(i + 1, j);
      if (!in(i + 1, j)) next[corner(i + 1, j)] = corner(i + 1, j + 1);
      if (!in(i, j + 1)) next[corner(i + 1, j + 1)] = corner(i, j + 1);
      if (!in(i - 1, j)) next[corner(i, j + 1)] = corner(i, j);
    }
  const auto point = [&](std::int64_t k) {
    return Vec2{g.origin.x + static_cast<double>(k % stride) * g.cell,
                g.origin.y + static_cast<double>(k / stride) * g.cell};
  };
  std::vector<Vec2> outer;
  std::vector<std::vector<Vec2>> holes;
  while (!next.empty()) {
    // From the loop's lowest corner (a corner of the outline: nothing precedes it in a row).
    const std::int64_t first = next.begin()->first;
    std::vector<std::int64_t> loop;
    for (std::int64_t k = first;;) {
      loop.push_back(k);
      const auto it = next.find(k);
      const std::int64_t to = it->second;
      next.erase(it);
      if (to == first) break;
      k = to;
    }
    // Corners only: a vertex where the outline turns.
    std::vector<Vec2> ring;
    double twice_area = 0.0;
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::int64_t before = loop[(k + n - 1) % n], at = loop[k], after = loop[(k + 1) % n];
      if (at - before != after - at) ring.push_back(point(at));
    }
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
      twice_area += a.x * b.y - b.x * a.y;
    }
    if (twice_area > 0.0)
      outer = std::move(ring);
    else
      holes.push_back(std::move(ring));
  }
  return std::make_unique<Environment>(std::move(outer), std::move(holes));
}

}  // namespace

}  // namespace covsim
