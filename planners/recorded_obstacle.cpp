#include "planners/recorded_obstacle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/ring_validation.hpp"

namespace covsim {

RecordedObstacle::RecordedObstacle(const std::vector<Vec2>& walked, int dir, double tolerance)
    : tolerance_(tolerance) {
  for (Vec2 p : walked) {
    if (ring_.empty() || beyond(p, ring_.back(), tolerance)) ring_.push_back(p);
  }
  while (ring_.size() > 1 && within(ring_.back(), ring_.front(), tolerance))
    ring_.pop_back();  // the walk ended where it began
  if (dir < 0) std::reverse(ring_.begin(), ring_.end());
  double area2 = 0.0;
  for (std::size_t k = 0; k < ring_.size(); ++k) {
    const Vec2 a = ring_[k], b = ring_[(k + 1) % ring_.size()];
    start_arc_.push_back(perimeter_);
    perimeter_ += distance(a, b);
    area2 += cross(a, b);
  }
  outer_ = area2 > 0.0;
}

bool RecordedObstacle::encloses(Vec2 p) const {
  if (ring_.size() < 3 || on_boundary(p, tolerance_)) return false;
  return inside_ring(ring_, p) != outer_;
}

bool RecordedObstacle::on_boundary(Vec2 p, double within) const {
  return ring_.empty() || distance(closest(p).point, p) <= within;
}

RingPlace RecordedObstacle::closest(Vec2 p) const {
  RingPlace best{ring_.empty() ? p : ring_.front(), 0.0};
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < ring_.size(); ++k) {
    const Vec2 a = ring_[k], b = ring_[(k + 1) % ring_.size()];
    const Vec2 q = project_to_segment(p, a, b).point;
    if (distance(q, p) < d) {
      d = distance(q, p);
      best = {q, start_arc_[k] + distance(a, q)};
    }
  }
  return best;
}

double RecordedObstacle::arc(RingPlace from, RingPlace to, int dir) const {
  if (perimeter_ <= 0.0) return 0.0;
  const double forward = std::fmod(to.arc - from.arc + perimeter_, perimeter_);
  return dir > 0 ? forward : std::fmod(perimeter_ - forward, perimeter_);
}

}  // namespace covsim
