#pragma once
// Which map a map planner plans on, a scenario choice (planner.map): "given", Ω itself (the
// paper's setting when Ω is known), or "sensed", the walls its robot's readings showed with
// unseen space free (planners/sensed_map_planner); "sensed" is implied when the robots do not
// know Ω (environment.known "boundary" or "none").
#include <string_view>

#include "core/param_schema.hpp"

namespace covsim {

inline constexpr std::string_view kPlannerMapKey = "map";

// The parameter, for the schemas of the planners that offer the choice.
ParamSpec planner_map_param();
// Whether a planner's parameters ask for the sensed map (unset: the given one).
bool plans_on_sensed_map(const Params& params);
// Throws ParamError("resolution") when cells of side h over Ω's bounding box (and the sensed
// map's margin) would number more than 2^24.
void check_grid_resolution(const Environment& env, double h);

}  // namespace covsim
