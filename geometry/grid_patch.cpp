#include "geometry/grid_patch.hpp"

#include <algorithm>
#include <utility>

#include "geometry/cell_walk.hpp"

namespace covsim {

namespace {

// Sorted cell indices (j · nx + i) as runs along rows.
std::vector<LatticeRun> runs_of(const std::vector<std::int64_t>& cells, std::int32_t nx) {
  std::vector<LatticeRun> out;
  for (const std::int64_t c : cells) {
    const auto j = static_cast<std::int32_t>(c / nx), i = static_cast<std::int32_t>(c % nx);
    if (!out.empty() && out.back().j == j && out.back().i1 + 1 == i) {
      out.back().i1 = i;
      continue;
    }
    out.push_back(LatticeRun{j, i, i});
  }
  return out;
}

}  // namespace

GridPatch inverse_sensor_model(const KnownLattice& grid, const Scan& scan) {
  GridPatch patch;
  const std::int32_t nx = grid.nx(), ny = grid.ny();
  std::vector<std::int64_t> hit;
  for (const VisiblePiece& p : scan.pieces)
    for_each_cell_on(grid.origin(), grid.cell(), p.a, p.b, [&](std::int32_t i, std::int32_t j) {
      if (i >= 0 && j >= 0 && i < nx && j < ny) hit.push_back(std::int64_t{j} * nx + i);
      return true;
    });
  std::sort(hit.begin(), hit.end());
  hit.erase(std::unique(hit.begin(), hit.end()), hit.end());
  patch.hits = runs_of(hit, nx);
  // The fan's cells less the hits, run by run.
  std::size_t h = 0;
  for (const LatticeRun& r : grid.runs(scan.fan)) {
    const std::int64_t row = std::int64_t{r.j} * nx;
    while (h < hit.size() && hit[h] < row + r.i0)
      ++h;
    std::int32_t from = r.i0;
    for (; h < hit.size() && hit[h] <= row + r.i1; ++h) {
      const auto i = static_cast<std::int32_t>(hit[h] - row);
      if (i > from) patch.misses.push_back(LatticeRun{r.j, from, i - 1});
      from = i + 1;
    }
    if (from <= r.i1) patch.misses.push_back(LatticeRun{r.j, from, r.i1});
  }
  return patch;
}

std::vector<GridPatch> split_patch(GridPatch patch, std::uint32_t max_bytes) {
  std::vector<GridPatch> out;
  if (patch.bytes() <= max_bytes) {
    out.push_back(std::move(patch));
    return out;
  }
  const std::size_t per = std::max<std::size_t>(1, (max_bytes - 4) / 6);
  GridPatch part;
  const auto add = [&](const LatticeRun& r, bool is_hit) {
    if (part.hits.size() + part.misses.size() == per) {
      out.push_back(std::move(part));
      part = GridPatch{};
    }
    (is_hit ? part.hits : part.misses).push_back(r);
  };
  for (const LatticeRun& r : patch.hits)
    add(r, true);
  for (const LatticeRun& r : patch.misses)
    add(r, false);
  if (!part.empty()) out.push_back(std::move(part));
  return out;
}

}  // namespace covsim
