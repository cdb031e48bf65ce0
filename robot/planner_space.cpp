#include "robot/planner_space.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace covsim {

PlannerSpace::PlannerSpace(const Environment& env, const ConfigurationSpace& free, double radius,
                           double inflation, double inflation_sigmas)
    : free_(free) {
  if (!(inflation > 0.0)) return;
  try {
    inflated_ = std::make_unique<ConfigurationSpace>(env, radius + inflation);
  } catch (const std::exception& e) {
    throw std::invalid_argument(fmt::format(
        "robots.inflation: Ω shrunk by the radius and {} standard deviations of the position "
        "estimate ({} m in all) leaves the map planners no free space ({})",
        inflation_sigmas, radius + inflation, e.what()));
  }
}

PlannerSpace::~PlannerSpace() = default;

std::size_t PlannerSpace::add(Vec2 start, std::size_t free_part) {
  std::size_t k = free_part;
  if (inflated_) {
    if (const auto holding = inflated_->part_of(start)) {
      k = *holding;
    } else {
      double nearest = INFINITY;
      for (std::size_t q = 0; q < inflated_->part_count(); ++q) {
        const Environment& e = inflated_->part(q);
        const double d = distance(start, e.closest_point(start));
        if (d < nearest) nearest = d, k = q;
      }
    }
  }
  part_.push_back(k);
  return k;
}

std::size_t PlannerSpace::part_count() const {
  return inflated_ ? inflated_->part_count() : free_.part_count();
}

const Environment& PlannerSpace::part(std::size_t k) const {
  return inflated_ ? inflated_->part(k) : free_.part(k);
}

}  // namespace covsim
