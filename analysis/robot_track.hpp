#pragma once
// What a run recorded of one robot, in time order: its position, virtual generator and
// targets after each motion step (the start first). Figures and videos draw from it.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/geometry/vec2.hpp"

namespace covsim {

struct RobotTrack {
  std::vector<double> t;
  std::vector<Vec2> position, virtual_generator, virtual_target, real_target;

  void push(double time, Vec2 p, Vec2 v, Vec2 vt, Vec2 rt) {
    t.push_back(time);
    position.push_back(p);
    virtual_generator.push_back(v);
    virtual_target.push_back(vt);
    real_target.push_back(rt);
  }
  // The last record at or before `time` (the first if none).
  std::size_t at(double time) const {
    const auto it = std::upper_bound(t.begin(), t.end(), time);
    return it == t.begin() ? 0 : static_cast<std::size_t>(it - t.begin()) - 1;
  }
  // The records with a time in [t0, t1]: indices [first, last).
  std::pair<std::size_t, std::size_t> window(double t0, double t1) const {
    const auto a = std::lower_bound(t.begin(), t.end(), t0);
    const auto b = std::upper_bound(t.begin(), t.end(), t1);
    return {static_cast<std::size_t>(a - t.begin()), static_cast<std::size_t>(b - t.begin())};
  }
};

}  // namespace covsim
