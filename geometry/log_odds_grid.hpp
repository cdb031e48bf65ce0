#pragma once
// An occupancy grid in log-odds form (Probabilistic Robotics, ch. 9): each cell holds
// log(p / (1 - p)) of being occupied, 0 (p = 0.5) before any reading, and a reading's hits and
// misses (grid_patch.hpp) add the inverse sensor model's log-odds. As in OctoMap (Hornung et
// al., 2013) the values are clamped, so that a cell seen often can still change its state
// when the world, or the pose the readings were placed at, says otherwise. A cell counts as
// occupied when its log-odds is above 0.
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/cell_region.hpp"
#include "geometry/grid_patch.hpp"
#include "geometry/known_lattice.hpp"

namespace covsim {

class LogOddsGrid {
 public:
  // OctoMap's clamping thresholds, as probabilities.
  static constexpr double kClampLow = 0.1192, kClampHigh = 0.971;

  // On the lattice's cells; p_hit and p_miss the inverse sensor model's probabilities of
  // occupation for a hit and a miss (p_hit > 0.5 > p_miss).
  LogOddsGrid(const KnownLattice& frame, double p_hit, double p_miss);

  const CellGrid& grid() const { return grid_; }
  // Adds a reading's hits and misses; how many cells changed state (occupied or not).
  std::size_t apply(const GridPatch& patch);
  double log_odds(std::size_t c) const { return l_[c]; }
  bool occupied(std::size_t c) const { return l_[c] > 0.0; }
  // Whether some reading told cell c anything.
  bool observed(std::size_t c) const { return seen_[c] != 0; }
  // Changes whenever a cell changes state.
  std::uint64_t version() const { return version_; }

 private:
  std::size_t add(const std::vector<LatticeRun>& runs, double l);

  CellGrid grid_;
  double hit_, miss_, low_, high_;
  std::vector<double> l_;
  std::vector<std::uint8_t> seen_;
  std::uint64_t version_ = 0;
};

}  // namespace covsim
