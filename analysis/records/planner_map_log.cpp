#include "analysis/records/planner_map_log.hpp"

namespace covsim {

void PlannerMapLog::record(double t, const std::vector<Robot>& robots) {
  // The pictures of the planners that keep a map (none, and nothing kept, for the others),
  // and the robots of each map in the order of their first robot (not of the maps'
  // addresses: the file is the same from run to run).
  std::vector<std::pair<std::uint32_t, PlannerPicture>> pictures;
  std::vector<std::pair<const void*, std::vector<std::uint32_t>>> maps;
  std::unordered_map<const void*, std::size_t> index;
  for (std::uint32_t i = 0; i < robots.size(); ++i) {
    PlannerPicture p = robots[i].planner->picture();
    if (p.map == nullptr) continue;
    const auto [it, fresh] = index.try_emplace(p.map, maps.size());
    if (fresh) maps.emplace_back(p.map, std::vector<std::uint32_t>{});
    maps[it->second].second.push_back(static_cast<std::uint32_t>(pictures.size()));
    pictures.emplace_back(i, std::move(p));
  }
  // A map's walls keep their order and only extend: each is new, longer, or as it was.
  for (const auto& [m, users] : maps) {
    const auto& walls = pictures[users.front()].second.walls;
    auto& last = walls_[m];
    // Written once, robot unset, when every robot shares the map; else under each robot that
    // uses it (with bodies, each part of the free space has its own shared map).
    const bool everyone = users.size() == robots.size();
    for (std::size_t k = 0; k < walls.size(); ++k) {
      if (k < last.size() && walls[k] == last[k]) continue;
      if (everyone) {
        record_.walls.push_back({t, std::nullopt, walls[k].first, walls[k].second});
      } else {
        for (const std::uint32_t u : users)
          record_.walls.push_back({t, pictures[u].first, walls[k].first, walls[k].second});
      }
    }
    last = walls;
  }
  ways_.resize(robots.size());
  for (auto& [i, p] : pictures) {
    std::vector<Vec2> way = std::move(p.path);
    if (way.size() < 2) way.clear();
    // A robot's first way is written unless it has none; after that, each change.
    if (ways_[i] ? *ways_[i] == way : way.empty()) continue;
    record_.ways.push_back({t, i, way});
    ways_[i] = std::move(way);
  }
}

}  // namespace covsim
