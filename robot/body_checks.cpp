#include "robot/body_checks.hpp"

#include <algorithm>
#include <cmath>

namespace covsim {

BodyChecks::BodyChecks(const Environment& env, const ConfigurationSpace& space, double radius,
                       double dt)
    : space_(space), radius_(radius), tolerance_(env.tolerance()), dt_(dt) {}

void BodyChecks::arrived(Vec2 position) {
  if (space_.overlaps_boundary(position)) ++wall_contacts_;
}

void BodyChecks::after_tick(const std::vector<Robot>& robots) {
  // A sweep along x: only pairs nearer in x than both the least gap so far and a contact
  // need a distance.
  const double r2 = 2.0 * radius_;
  const double touch = r2 - tolerance_;
  std::vector<std::uint32_t> order(robots.size());
  for (std::uint32_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return robots[a].position.x < robots[b].position.x ||
           (robots[a].position.x == robots[b].position.x && a < b);
  });
  std::vector<bool> touching(robots.size(), false);
  double least = INFINITY;
  for (std::size_t a = 0; a < order.size(); ++a) {
    const Vec2 p = robots[order[a]].position;
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const Vec2 q = robots[order[b]].position;
      if (q.x - p.x >= std::max(least, r2)) break;
      const double d = distance(p, q);
      least = std::min(least, d);
      if (d < touch) touching[order[a]] = touching[order[b]] = true;
    }
  }
  if (order.size() >= 2) gap_min_ = std::fmin(gap_min_, least - r2);
  for (bool t : touching)
    if (t) contact_time_ += dt_;
}

}  // namespace covsim
