#include "net/receiver_grid.hpp"

#include <algorithm>
#include <cmath>

namespace covsim {

namespace {
// A cell index; clamped so that an absurdly small range cannot overflow the conversion
// (clamped cells only gather more candidates, which the distance test then drops).
std::int64_t index_of(double v, double cell) {
  return static_cast<std::int64_t>(std::clamp(std::floor(v / cell), -1e15, 1e15));
}

std::uint64_t pack(std::int64_t cx, std::int64_t cy) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(cx)) << 32) |
         static_cast<std::uint32_t>(cy);
}
}  // namespace

ReceiverGrid::ReceiverGrid(double range, std::span<const Vec2> positions)
    : range_(range), slack_(0.25 * range), cell_(range + 2.0 * slack_) {
  anchor_.assign(positions.begin(), positions.end());
  filed_in_.resize(positions.size());
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    filed_in_[i] = cell_key(positions[i]);
    cells_[filed_in_[i]].push_back(i);
  }
}

std::uint64_t ReceiverGrid::cell_key(Vec2 p) const {
  return pack(index_of(p.x, cell_), index_of(p.y, cell_));
}

void ReceiverGrid::moved(std::uint32_t i, Vec2 p) {
  const Vec2 d = p - anchor_[i];
  if (d.x * d.x + d.y * d.y <= slack_ * slack_) return;
  anchor_[i] = p;
  const std::uint64_t key = cell_key(p);
  if (key == filed_in_[i]) return;
  std::vector<std::uint32_t>& from = cells_[filed_in_[i]];
  *std::find(from.begin(), from.end(), i) = from.back();
  from.pop_back();
  cells_[key].push_back(i);
  filed_in_[i] = key;
}

void ReceiverGrid::candidates(Vec2 p, std::vector<std::uint32_t>& out) const {
  out.clear();
  const std::int64_t cx = index_of(p.x, cell_), cy = index_of(p.y, cell_);
  // Anchors farther than range + slack cannot be in range; the margin covers rounding.
  const double reach = (range_ + slack_) * (1.0 + 1e-9);
  for (std::int64_t x = cx - 1; x <= cx + 1; ++x) {
    for (std::int64_t y = cy - 1; y <= cy + 1; ++y) {
      const auto it = cells_.find(pack(x, y));
      if (it == cells_.end()) continue;
      for (std::uint32_t j : it->second) {
        const Vec2 d = anchor_[j] - p;
        if (d.x * d.x + d.y * d.y <= reach * reach) out.push_back(j);
      }
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace covsim
