#include "analysis/records/planner_map_record.hpp"

#include <fmt/format.h>

namespace covsim {

PlannerPicture PlannerMapRecord::at(std::uint32_t robot, double t) const {
  PlannerPicture p;
  for (const Wall& w : walls) {
    if (w.t > t) break;
    if (!w.robot || *w.robot == robot) p.walls.emplace_back(w.a, w.b);
  }
  for (const Way& w : ways) {
    if (w.t > t) break;
    if (w.robot == robot) p.path = w.points;
  }
  return p;
}

std::string PlannerMapRecord::csv() const {
  std::string out(kHeader);
  out += '\n';
  // In time order, walls before ways at one time.
  std::size_t i = 0, j = 0;
  while (i < walls.size() || j < ways.size()) {
    if (i < walls.size() && (j == ways.size() || walls[i].t <= ways[j].t)) {
      const Wall& w = walls[i++];
      fmt::format_to(std::back_inserter(out), "{},wall,{},{},{},{},{}\n",
                     w.robot ? fmt::to_string(*w.robot) : std::string(), w.t, w.a.x, w.a.y, w.b.x,
                     w.b.y);
      continue;
    }
    const Way& w = ways[j++];
    if (w.points.size() < 2) {
      fmt::format_to(std::back_inserter(out), "{},stop,{},,,,\n", w.robot, w.t);
      continue;
    }
    for (std::size_t k = 0; k + 1 < w.points.size(); ++k)
      fmt::format_to(std::back_inserter(out), "{},path,{},{},{},{},{}\n", w.robot, w.t,
                     w.points[k].x, w.points[k].y, w.points[k + 1].x, w.points[k + 1].y);
  }
  return out;
}

}  // namespace covsim
