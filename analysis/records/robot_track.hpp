#pragma once
// What a run recorded of one robot, in time order: its position, virtual generator and
// targets after each motion step (the start first), to a tolerance. Figures and videos draw
// from it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

// The tolerance figures keep tracks to in Ω of this diameter: 1e-4 of it, a tenth of a pixel
// on a picture 1 000 pixels across.
inline double track_tolerance(double diameter) {
  return 1e-4 * diameter;
}

struct RobotTrack {
  // Records within this of the last one kept (in every coordinate of every point) are not
  // kept, except the newest: memory grows with motion, not with time (every robot records
  // every step, settled or creeping toward its target), and the drawn paths differ from
  // the recorded ones by at most this. 0 merges only exact repeats.
  double tolerance = 0.0;
  std::vector<double> t;
  std::vector<Vec2> position, virtual_generator, virtual_target, real_target;

  // The last record is provisional while it lies within the tolerance of the one before
  // it: a newer record that does too takes its place, so a stay is its first and last
  // records and at() answers within the tolerance.
  void push(double time, Vec2 p, Vec2 v, Vec2 vt, Vec2 rt) {
    const std::size_t n = t.size();
    if (n >= 2 && near(n - 2, p, v, vt, rt) &&
        near(n - 2, position[n - 1], virtual_generator[n - 1], virtual_target[n - 1],
             real_target[n - 1])) {
      t[n - 1] = time;
      position[n - 1] = p;
      virtual_generator[n - 1] = v;
      virtual_target[n - 1] = vt;
      real_target[n - 1] = rt;
      return;
    }
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
  // The records with a time in [t0, t1], and the one a stay under way at t0 began with:
  // indices [first, last).
  std::pair<std::size_t, std::size_t> window(double t0, double t1) const {
    auto a = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), t0) - t.begin());
    const auto b = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), t1) - t.begin());
    if (a > 0 && a < t.size() &&
        near(a - 1, position[a], virtual_generator[a], virtual_target[a], real_target[a]))
      --a;
    return {a, b};
  }

 private:
  bool near(std::size_t i, Vec2 p, Vec2 v, Vec2 vt, Vec2 rt) const {
    const auto close = [this](Vec2 a, Vec2 b) {
      return std::fabs(a.x - b.x) <= tolerance && std::fabs(a.y - b.y) <= tolerance;
    };
    return close(position[i], p) && close(virtual_generator[i], v) &&
           close(virtual_target[i], vt) && close(real_target[i], rt);
  }
};

}  // namespace covsim
