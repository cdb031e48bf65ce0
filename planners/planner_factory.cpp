#include "planners/planner_factory.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "planners/tangent_bug.hpp"

namespace covsim {

const std::vector<std::string_view>& planner_names() {
  static const std::vector<std::string_view> names{"tangent_bug"};
  return names;
}

std::unique_ptr<Planner> make_planner(std::string_view name, const Environment& env,
                                      const SensorSpec& sensor) {
  if (name == "tangent_bug") {
    double boundary = 0.0;
    for (const BoundaryEdge& e : env.boundary())
      boundary += distance(e.a, e.b);
    TangentBugParams p = TangentBugParams::for_environment(env.diameter(), boundary);
    // A decrease smaller than the sensor's noise is no progress: three standard deviations.
    p.progress = std::max(p.progress, 3.0 * sensor.noise_sigma);
    return std::make_unique<TangentBug>(p);
  }
  throw std::invalid_argument("unknown planner \"" + std::string(name) + "\"");
}

}  // namespace covsim
