#include "robot/coverage_config.hpp"

#include <algorithm>
#include <cmath>

namespace covsim {

double robot_spacing(const Environment& env, std::size_t n) {
  // No robots (a scenario read for its cells): the whole area is one robot's.
  return std::sqrt(env.area() / static_cast<double>(std::max<std::size_t>(n, 1)));
}

std::string_view to_string(ProjectionPolicy p) {
  for (const auto& [policy, name] : kProjectionPolicies) {
    if (policy == p) return name;
  }
  return "unknown";
}

std::optional<ProjectionPolicy> projection_named(std::string_view name) {
  for (const auto& [policy, n] : kProjectionPolicies) {
    if (n == name) return policy;
  }
  return std::nullopt;
}

}  // namespace covsim
