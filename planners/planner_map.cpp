#include "planners/planner_map.hpp"

#include <cmath>

#include "geometry/environment.hpp"

namespace covsim {

ParamSpec planner_map_param() {
  return ParamSpec::choice(std::string(kPlannerMapKey), {"given", "sensed"},
                           "what it plans on: Ω itself, or the walls its robot sensed, unseen "
                           "space free (replanned when a reading meets its path)")
      .derived("\"given\" when Ω is known (environment.known \"full\"), \"sensed\" otherwise",
               [](const Environment&) { return ParamValue{std::string("given")}; });
}

bool plans_on_sensed_map(const Params& params) {
  return params.has(kPlannerMapKey) && params.text(kPlannerMapKey) == "sensed";
}

void check_grid_resolution(const Environment& env, double h) {
  const Vec2 size = env.bounds().size();
  constexpr double kMaxCells = double(1 << 24);
  if ((std::ceil(size.x / h) + 4.0) * (std::ceil(size.y / h) + 4.0) > kMaxCells)
    throw ParamError("resolution",
                     "resolution too fine for this environment: more than 16777216 cells");
}

}  // namespace covsim
