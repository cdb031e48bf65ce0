#include "analysis/figures/map_legend.hpp"

#include <vector>

#include "analysis/figures/robot_palette.hpp"

namespace covsim {

Legend map_legend(const Layers& layers, const Marks& m, const MapView& view, double font,
                  bool unknown_area, bool planner_map) {
  std::vector<LegendEntry> e;
  const Vec2 half{0.9 * font, 0};
  const auto line = [half](Stroke s) {
    return [half, s](Canvas& c, Vec2 p) { c.line(p - half, p + half, s); };
  };
  const Colour first = robot_colour(0);
  if (layers.has(Layer::paths)) {
    // Three robots' colours: one colour per robot.
    e.push_back({"robot path", [half, m](Canvas& c, Vec2 p) {
                   for (int k = 0; k < 3; ++k)
                     c.line(p - half + Vec2{k * 0.7 * half.x, 0},
                            p - half + Vec2{(k * 0.7 + 0.6) * half.x, 0}, m.path(robot_colour(k)));
                 }});
    e.push_back({"start", [m, first](Canvas& c, Vec2 p) { m.start(c, p, first); }});
  }
  if (layers.has(Layer::virtual_paths))
    e.push_back({"virtual generator path", line(m.virtual_path(first))});
  if (layers.has(Layer::robots))
    e.push_back({layers.has(Layer::ids) ? "robot (ID)" : "robot",
                 [m, first](Canvas& c, Vec2 p) { m.robot(c, p, first); }});
  if (layers.has(Layer::generators))
    e.push_back({"virtual generator", [m, first](Canvas& c, Vec2 p) { m.generator(c, p, first); }});
  if (layers.has(Layer::targets)) {
    e.push_back({"virtual target", [m](Canvas& c, Vec2 p) { m.target(c, p); }});
    e.push_back({"projected target", [m](Canvas& c, Vec2 p) { m.projected_target(c, p); }});
  }
  if (layers.has(Layer::cells)) e.push_back({"virtual partition", line(m.cells())});
  if (layers.has(Layer::real_cells)) e.push_back({"real partition", line(m.real_cells())});
  if (layers.has(Layer::obstacles))
    e.push_back({"obstacle", [half](Canvas& c, Vec2 p) {
                   c.rectangle(p - half - Vec2{0, 0.4 * half.x}, p + half + Vec2{0, 0.4 * half.x},
                               Marks::obstacle());
                 }});
  if (layers.has(Layer::obstacles) && unknown_area)
    e.push_back({"not yet mapped", [half](Canvas& c, Vec2 p) {
                   c.rectangle(p - half - Vec2{0, 0.4 * half.x}, p + half + Vec2{0, 0.4 * half.x},
                               Marks::unknown());
                 }});
  if (planner_map) {
    e.push_back({"walls the planner's map held", line(m.planner_wall())});
    e.push_back({"the planner's way ahead", line(m.planner_way(first))});
  }
  if (layers.has(Layer::density))
    e.push_back({view.uniform() ? "uniform density φ" : "density φ",
                 [&view, font](Canvas& c, Vec2 p) { view.draw_density_swatch(c, p, font); }});
  return Legend(std::move(e), font);
}

}  // namespace covsim
