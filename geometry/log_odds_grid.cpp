#include "geometry/log_odds_grid.hpp"

#include <algorithm>
#include <stdexcept>

namespace covsim {

namespace {

double log_odds_of(double p) {
  return std::log(p / (1.0 - p));
}

}  // namespace

LogOddsGrid::LogOddsGrid(const KnownLattice& frame, double p_hit, double p_miss)
    : grid_{frame.origin(), frame.cell(), frame.nx(), frame.ny()},
      hit_(log_odds_of(p_hit)),
      miss_(log_odds_of(p_miss)),
      low_(log_odds_of(kClampLow)),
      high_(log_odds_of(kClampHigh)),
      l_(grid_.size(), 0.0),
      seen_(grid_.size(), 0) {
  if (!(p_hit > 0.5 && p_hit < 1.0 && p_miss > 0.0 && p_miss < 0.5))
    throw std::invalid_argument("an occupancy grid needs 0.5 < p_hit < 1 and 0 < p_miss < 0.5");
}

std::size_t LogOddsGrid::add(const std::vector<LatticeRun>& runs, double l) {
  std::size_t changed = 0;
  for (const LatticeRun& r : runs)
    for (std::int32_t i = r.i0; i <= r.i1; ++i) {
      const std::size_t c = grid_.index(i, r.j);
      const bool before = l_[c] > 0.0;
      l_[c] = std::clamp(l_[c] + l, low_, high_);
      seen_[c] = 1;
      if ((l_[c] > 0.0) != before) ++changed;
    }
  return changed;
}

std::size_t LogOddsGrid::apply(const GridPatch& patch) {
  const std::size_t changed = add(patch.hits, hit_) + add(patch.misses, miss_);
  if (changed > 0) ++version_;
  return changed;
}

}  // namespace covsim
