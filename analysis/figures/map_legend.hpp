#pragma once
// The legend of a map (a scene or a video frame): an entry for each mark its layers draw,
// its symbol the mark itself.
#include "analysis/figures/layers.hpp"
#include "analysis/figures/legend.hpp"
#include "analysis/figures/map_view.hpp"
#include "analysis/figures/marks.hpp"

namespace covsim {

// `view` must outlive the legend (the density's swatch is drawn from it).
// unknown_area: the robots mapped Ω, and what they did not know yet is shaded. planner_map:
// one robot's planner's map and way are drawn.
Legend map_legend(const Layers& layers, const Marks& marks, const MapView& view, double font,
                  bool unknown_area = false, bool planner_map = false);

}  // namespace covsim
