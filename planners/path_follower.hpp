#pragma once
// Drives along a planned polyline, at most one step length per loop-2 step. A step ends at
// the next waypoint rather than cutting its corner, since the chord round a reflex vertex
// would cross the obstacle.
#include <cstddef>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

class PathFollower {
 public:
  // path[0] is where the robot stands; the rest are the waypoints.
  void assign(std::vector<Vec2> path);
  void clear() { path_.clear(), next_ = 0; }
  bool empty() const { return path_.empty(); }
  // Whether the last waypoint has been reached.
  bool done() const { return next_ >= path_.size(); }
  // The whole path, and the index of the waypoint driven to next.
  const std::vector<Vec2>& path() const { return path_; }
  std::size_t next() const { return next_; }
  // The point at most max_step from `position` along the path (the robot may lag behind
  // the path by up to `tolerance`).
  Vec2 advance(Vec2 position, double max_step, double tolerance);

 private:
  std::vector<Vec2> path_;
  std::size_t next_ = 0;
};

}  // namespace covsim
