#pragma once
// One robot's planner's map as the scene figure and the video draw it: the walls its map held
// (dark orange) and the way it had ahead (dashed, in the robot's colour). replay.html draws
// the same from its own script.
#include "analysis/figures/canvas.hpp"
#include "analysis/figures/map_view.hpp"
#include "analysis/figures/marks.hpp"
#include "planners/planner.hpp"

namespace covsim {

void draw_planner_map(Canvas& c, const MapView& view, const Marks& marks, const PlannerPicture& p,
                      Colour way);

}  // namespace covsim
