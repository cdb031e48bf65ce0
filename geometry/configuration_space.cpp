#include "geometry/configuration_space.hpp"

#include <fmt/format.h>

#include <cmath>

#include "geometry/geometry_error.hpp"
#include "geometry/polygon_offset.hpp"

namespace covsim {

ConfigurationSpace::ConfigurationSpace(const Environment& env, double radius)
    : env_(&env), radius_(radius) {
  if (!(std::isfinite(radius) && radius >= 0.0))
    throw GeometryError(fmt::format("a robot's radius must be finite and >= 0, found {}", radius));
  if (radius == 0.0) return;
  for (PolygonWithHoles& p : inset_polygon(env.rings(), radius)) {
    try {
      parts_.push_back(std::make_unique<const Environment>(std::move(p.outer), std::move(p.holes)));
    } catch (const GeometryError&) {
      // A sliver the offset left thinner than rounding: no room for a body there.
    }
  }
  if (parts_.empty())
    throw GeometryError(fmt::format(
        "no point of the environment is {} m from its boundary: a robot of radius {} m fits "
        "nowhere",
        radius, radius));
}

ConfigurationSpace::ConfigurationSpace(const Environment& env, double radius,
                                       std::vector<std::unique_ptr<const Environment>> parts)
    : env_(&env), radius_(radius), parts_(std::move(parts)) {
  if (parts_.empty())
    throw GeometryError(fmt::format("a robot of radius {} m fits nowhere", radius));
}

std::optional<std::size_t> ConfigurationSpace::part_of(Vec2 p) const {
  if (parts_.empty()) return env_->contains(p) ? std::optional<std::size_t>(0) : std::nullopt;
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    if (parts_[k]->contains(p)) return k;
  }
  return std::nullopt;
}

bool ConfigurationSpace::overlaps_boundary(Vec2 p) const {
  return !env_->contains(p) || env_->boundary_distance(p) < radius_ - env_->tolerance();
}

}  // namespace covsim
