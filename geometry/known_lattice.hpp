#pragma once
// Which parts of Ω a robot has seen to be free, on a lattice of square cells over Ω's
// bounding box: a cell is known once its centre lies in a scan's fan. The area it measures is
// exact to the cells along the fans' edges (a band one cell wide), and it never marks a cell
// whose centre lies in an obstacle: the fans lie in Ω.
#include <cstdint>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

class Environment;

// Cells (i0..i1, j) of a lattice in a row: how a polygon's cells are kept, to be marked on
// many lattices of the same box without filling the polygon again.
struct LatticeRun {
  std::int32_t j, i0, i1;
};

class KnownLattice {
 public:
  KnownLattice() = default;
  // `cells` across the longer side of the box.
  KnownLattice(const Box& box, std::uint32_t cells);
  // The lattice of the cells whose centre lies in Ω.
  static KnownLattice of_free_space(const Environment& env, std::uint32_t cells);

  std::int32_t nx() const { return nx_; }
  std::int32_t ny() const { return ny_; }
  double cell() const { return cell_; }
  // The lower-left corner of cell (0, 0).
  Vec2 origin() const { return origin_; }
  Vec2 centre(std::int32_t i, std::int32_t j) const {
    return {origin_.x + (i + 0.5) * cell_, origin_.y + (j + 0.5) * cell_};
  }
  bool at(std::int32_t i, std::int32_t j) const {
    const std::size_t k = index(i, j);
    return ((bits_[k / 64] >> (k % 64)) & 1U) != 0;
  }
  void set(std::int32_t i, std::int32_t j) {
    const std::size_t k = index(i, j);
    bits_[k / 64] |= std::uint64_t{1} << (k % 64);
  }
  // The cells whose centre lies in the polygon (even-odd rule), as runs along rows.
  std::vector<LatticeRun> runs(const std::vector<Vec2>& polygon) const;
  // Marks the runs' cells; returns how many were new, and appends their indices (j · nx + i)
  // to `fresh` if given.
  std::uint64_t mark(const std::vector<LatticeRun>& runs,
                     std::vector<std::size_t>* fresh = nullptr);
  // Marks every cell whose centre lies in the polygon: mark(runs(polygon)).
  std::uint64_t fill(const std::vector<Vec2>& polygon, std::vector<std::size_t>* fresh = nullptr) {
    return mark(runs(polygon), fresh);
  }
  // Marks what the other lattice (of the same box and cells) marks; returns how many were new.
  std::uint64_t merge(const KnownLattice& other);
  std::uint64_t count() const;
  // Cells marked in both.
  std::uint64_t common(const KnownLattice& other) const;

 private:
  std::size_t index(std::int32_t i, std::int32_t j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(i);
  }
  Vec2 origin_;
  double cell_ = 0.0;
  std::int32_t nx_ = 0, ny_ = 0;
  std::vector<std::uint64_t> bits_;
};

}  // namespace covsim
