#include "planners/path_follower.hpp"

namespace covsim {

void PathFollower::assign(std::vector<Vec2> path) {
  path_ = std::move(path);
  next_ = path_.empty() ? 0 : 1;
}

Vec2 PathFollower::advance(Vec2 position, double max_step, double tolerance) {
  while (next_ < path_.size() && distance(position, path_[next_]) <= tolerance)
    ++next_;
  if (done()) return position;
  const Vec2 w = path_[next_];
  const double d = distance(position, w);
  if (d <= max_step) {
    ++next_;
    return w;
  }
  return position + (max_step / d) * (w - position);
}

}  // namespace covsim
