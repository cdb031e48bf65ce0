#include "analysis/figures/planner_map_view.hpp"

#include <vector>

namespace covsim {

void draw_planner_map(Canvas& c, const MapView& view, const Marks& marks, const PlannerPicture& p,
                      Colour way) {
  for (const auto& [a, b] : p.walls)
    c.line(view.to_px(a), view.to_px(b), marks.planner_wall());
  std::vector<Vec2> px;
  for (const Vec2 q : p.path)
    px.push_back(view.to_px(q));
  if (px.size() >= 2) c.polyline(px, marks.planner_way(way));
}

}  // namespace covsim
