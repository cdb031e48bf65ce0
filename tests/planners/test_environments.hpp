#pragma once
// Environments that make planners work: a spiral corridor, a serpentine maze with pillars,
// a room with an obstacle, a comb-shaped room.
#include <vector>

#include "geometry/environment.hpp"

namespace covsim::test {

// The polygon of a corridor of width w around an axis-parallel polyline with right-angle
// turns (mitred corners).
inline std::vector<Vec2> corridor(const std::vector<Vec2>& centre, double w) {
  std::vector<Vec2> left, right;
  const std::size_t n = centre.size();
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 off{0, 0};
    for (int side : {-1, 1}) {
      if ((side < 0 && i == 0) || (side > 0 && i + 1 == n)) continue;
      const Vec2 d = side < 0 ? centre[i] - centre[i - 1] : centre[i + 1] - centre[i];
      off += perp(d / norm(d));
    }
    left.push_back(centre[i] + 0.5 * w * off);
    right.push_back(centre[i] - 0.5 * w * off);
  }
  std::vector<Vec2> ring = right;
  ring.insert(ring.end(), left.rbegin(), left.rend());
  return ring;
}

// A rectangular spiral corridor, 8 runs, winding inwards.
inline Environment spiral() {
  std::vector<Vec2> c{{0, 0}};
  const Vec2 dirs[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  double len = 4.0;
  for (int k = 0; k < 8; ++k) {
    c.push_back(c.back() + len * dirs[k % 4]);
    if (k % 2 == 1) len -= 1.0;
  }
  return Environment(corridor(c, 0.5), {});
}

// A serpentine corridor (a maze without choices) with pillars in some of its runs.
inline Environment serpentine() {
  std::vector<Vec2> c;
  for (int k = 0; k < 5; ++k) {
    const double x = 1.5 * k;
    if (k % 2 == 0) {
      c.push_back({x, 0});
      c.push_back({x, 4});
    } else {
      c.push_back({x, 4});
      c.push_back({x, 0});
    }
  }
  return Environment(corridor(c, 0.8), {{{1.4, 1.5}, {1.6, 1.5}, {1.6, 2.0}, {1.4, 2.0}},
                                        {{4.4, 2.6}, {4.6, 2.6}, {4.6, 3.0}, {4.4, 3.0}}});
}

// A room with a U-shaped obstacle whose opening faces away from the start.
inline Environment room_with_cup() {
  return Environment(
      {{0, 0}, {6, 0}, {6, 4}, {0, 4}},
      {{{2, 1}, {4, 1}, {4, 3}, {3.8, 3}, {3.8, 1.2}, {2.2, 1.2}, {2.2, 3}, {2, 3}}});
}

// A comb-shaped room: a hall along the top with five teeth (walls of the outer ring) hanging
// down from it into the bottom part, making four bays open toward the hall.
inline Environment comb() {
  // The outer ring runs counter-clockwise; teeth are notches cut up from the bottom edge.
  std::vector<Vec2> ring{{0, 0}};
  for (int k = 1; k <= 4; ++k) {
    const double x = 2.0 * k;
    ring.push_back({x - 0.1, 0});
    ring.push_back({x - 0.1, 2.5});
    ring.push_back({x + 0.1, 2.5});
    ring.push_back({x + 0.1, 0});
  }
  ring.push_back({10, 0});
  ring.push_back({10, 4});
  ring.push_back({0, 4});
  return Environment(ring, {});
}

}  // namespace covsim::test
