#pragma once
// A grid path made straight where it can be: each kept waypoint is joined to the last of the
// run of later waypoints it sees (`sees(a, b)`: the leg a -> b is clear).
#include <cstddef>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

template <class Sees>
std::vector<Vec2> shorten(const std::vector<Vec2>& path, const Sees& sees) {
  std::vector<Vec2> out{path.front()};
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t j = i + 1;
    while (j + 1 < path.size() && sees(path[i], path[j + 1]))
      ++j;
    out.push_back(path[j]);
    i = j;
  }
  return out;
}

}  // namespace covsim
