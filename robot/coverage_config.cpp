#include "robot/coverage_config.hpp"

#include <algorithm>
#include <cmath>

namespace covsim {

double robot_spacing(const Environment& env, std::size_t n) {
  // No robots (a scenario read for its cells): the whole area is one robot's.
  return std::sqrt(env.area() / static_cast<double>(std::max<std::size_t>(n, 1)));
}

}  // namespace covsim
