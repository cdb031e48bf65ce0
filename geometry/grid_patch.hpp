#pragma once
// One range reading as an occupancy grid takes it: the inverse sensor model of Thrun,
// Burgard and Fox (Probabilistic Robotics, ch. 9.2), for a scan whose wall points are known
// along the whole turn. Cells whose closed square a seen wall meets are hits; cells whose
// centre lies in the reading's fan (the region it shows free, through the walls seen and,
// where no wall lies within range, to the range) and that no wall meets are misses; others
// learn nothing. The patch is what a robot sends of the reading: runs of cells along rows.
#include <cstdint>
#include <vector>

#include "geometry/known_lattice.hpp"
#include "geometry/scan.hpp"

namespace covsim {

struct GridPatch {
  std::vector<LatticeRun> hits, misses;
  // Its size in a message: the number of runs of each kind (2 bytes each), and each run's
  // row, first and last column (2 bytes each).
  std::uint32_t bytes() const {
    return 4 + 6 * static_cast<std::uint32_t>(hits.size() + misses.size());
  }
  bool empty() const { return hits.empty() && misses.empty(); }
};

// The reading's hits and misses on the lattice's cells (cells outside it left out).
GridPatch inverse_sensor_model(const KnownLattice& grid, const Scan& scan);

// A patch larger than max_bytes cut into patches of consecutive runs that each fit (hits
// first, then misses); a patch that fits is returned as it is.
std::vector<GridPatch> split_patch(GridPatch patch, std::uint32_t max_bytes);

}  // namespace covsim
