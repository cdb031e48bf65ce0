#include "geometry/known_lattice.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "geometry/environment.hpp"

namespace covsim {

KnownLattice::KnownLattice(const Box& box, std::uint32_t cells) {
  if (cells == 0 || box.empty()) throw std::invalid_argument("a lattice needs cells and a box");
  const Vec2 size = box.size();
  cell_ = std::max(size.x, size.y) / cells;
  nx_ = std::max(1, static_cast<std::int32_t>(std::ceil(size.x / cell_ - 1e-9)));
  ny_ = std::max(1, static_cast<std::int32_t>(std::ceil(size.y / cell_ - 1e-9)));
  origin_ = box.lo;
  bits_.assign((static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) + 63) / 64, 0);
}

KnownLattice KnownLattice::of_free_space(const Environment& env, std::uint32_t cells) {
  KnownLattice l(env.bounds(), cells);
  for (std::int32_t j = 0; j < l.ny_; ++j)
    for (std::int32_t i = 0; i < l.nx_; ++i)
      if (env.contains(l.centre(i, j))) l.set(i, j);
  return l;
}

std::vector<LatticeRun> KnownLattice::runs(const std::vector<Vec2>& polygon) const {
  std::vector<LatticeRun> out;
  if (polygon.size() < 3) return out;
  double lo = INFINITY, hi = -INFINITY;
  for (const Vec2& p : polygon) {
    lo = std::min(lo, p.y);
    hi = std::max(hi, p.y);
  }
  // Rows whose centre line crosses the polygon's extent.
  const auto j0 = std::max<std::int32_t>(
      0, static_cast<std::int32_t>(std::floor((lo - origin_.y) / cell_ - 0.5)));
  const auto j1 = std::min<std::int32_t>(
      ny_ - 1, static_cast<std::int32_t>(std::ceil((hi - origin_.y) / cell_ - 0.5)));
  std::vector<double> xs;
  for (std::int32_t j = j0; j <= j1; ++j) {
    const double y = origin_.y + (j + 0.5) * cell_;
    xs.clear();
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const Vec2 a = polygon[k], b = polygon[(k + 1) % polygon.size()];
      // Half-open in y: a vertex on the line counts once.
      if ((a.y <= y) == (b.y <= y)) continue;
      xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      // Cells whose centre x lies in [xs[k], xs[k + 1]].
      const auto i0 = std::max<std::int32_t>(
          0, static_cast<std::int32_t>(std::ceil((xs[k] - origin_.x) / cell_ - 0.5)));
      const auto i1 = std::min<std::int32_t>(
          nx_ - 1, static_cast<std::int32_t>(std::floor((xs[k + 1] - origin_.x) / cell_ - 0.5)));
      if (i0 <= i1) out.push_back({j, i0, i1});
    }
  }
  return out;
}

std::uint64_t KnownLattice::mark(const std::vector<LatticeRun>& runs,
                                 std::vector<std::size_t>* fresh) {
  std::uint64_t added = 0;
  for (const LatticeRun& r : runs) {
    // The run's bits, a word at a time.
    std::size_t k = index(r.i0, r.j);
    const std::size_t end = index(r.i1, r.j) + 1;
    while (k < end) {
      const std::size_t w = k / 64, lo = k % 64;
      const std::size_t hi = std::min<std::size_t>(64, lo + (end - k));
      const std::uint64_t mask = (hi == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << hi) - 1) &
                                 ~((std::uint64_t{1} << lo) - 1);
      std::uint64_t added_bits = mask & ~bits_[w];
      bits_[w] |= mask;
      added += static_cast<std::uint64_t>(std::popcount(added_bits));
      if (fresh != nullptr) {
        for (; added_bits != 0; added_bits &= added_bits - 1)
          fresh->push_back(w * 64 + static_cast<std::size_t>(std::countr_zero(added_bits)));
      }
      k = w * 64 + hi;
    }
  }
  return added;
}

std::uint64_t KnownLattice::merge(const KnownLattice& other) {
  if (other.bits_.size() != bits_.size()) throw std::invalid_argument("lattices differ");
  std::uint64_t added = 0;
  for (std::size_t k = 0; k < bits_.size(); ++k) {
    added += static_cast<std::uint64_t>(std::popcount(other.bits_[k] & ~bits_[k]));
    bits_[k] |= other.bits_[k];
  }
  return added;
}

std::uint64_t KnownLattice::count() const {
  std::uint64_t n = 0;
  for (const std::uint64_t w : bits_)
    n += static_cast<std::uint64_t>(std::popcount(w));
  return n;
}

std::uint64_t KnownLattice::common(const KnownLattice& other) const {
  std::uint64_t n = 0;
  for (std::size_t k = 0; k < bits_.size(); ++k)
    n += static_cast<std::uint64_t>(std::popcount(bits_[k] & other.bits_[k]));
  return n;
}

}  // namespace covsim
