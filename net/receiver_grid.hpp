#pragma once
// Who may hear a broadcast, without testing every robot: robots are filed in a uniform grid
// by an anchor, a position each keeps until it has moved more than a slack (a quarter of the
// range) away from it. Every robot within range of a point then has its anchor within
// range + slack of it, so it is filed in the 3 × 3 cells around the point (cells are
// range + 2 slack wide, the extra slack absorbing rounding). A broadcast costs the robots
// near the sender, not N, and a motion step O(1).
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

class ReceiverGrid {
 public:
  ReceiverGrid(double range, std::span<const Vec2> positions);
  // Robot i is now at p.
  void moved(std::uint32_t i, Vec2 p);
  // Every robot that may be within range of p (a superset: the channel decides), in
  // increasing index, into out.
  void candidates(Vec2 p, std::vector<std::uint32_t>& out) const;

 private:
  std::uint64_t cell_key(Vec2 p) const;

  double range_, slack_, cell_;
  std::vector<Vec2> anchor_;
  std::vector<std::uint64_t> filed_in_;  // each robot's cell key
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace covsim
