#include "analysis/records/state_difference.hpp"

#include <map>
#include <utility>

namespace covsim {

void TrajectoryCapture::on_motion(SimTime t, const Robot& r) {
  rows_.push_back(TrajectoryRow{t.seconds(), r.id, r.position, r.virtual_generator,
                                r.virtual_target, r.real_target});
}

std::optional<StateDifference> first_state_difference(const std::vector<TrajectoryRow>& recorded,
                                                      const std::vector<TrajectoryRow>& replayed) {
  // A recorded row stands for the robot's last step at its time (a thinned recording keeps
  // some steps only; the first row of a robot is its start, at t = 0).
  std::map<std::pair<double, std::uint32_t>, const TrajectoryRow*> last;
  for (const TrajectoryRow& r : replayed)
    last[{r.t, r.robot}] = &r;
  for (const TrajectoryRow& r : recorded) {
    const auto it = last.find({r.t, r.robot});
    if (it == last.end()) continue;
    const TrajectoryRow& p = *it->second;
    const std::pair<const char*, std::pair<Vec2, Vec2>> states[] = {
        {"position", {r.position, p.position}},
        {"virtual generator", {r.virtual_generator, p.virtual_generator}},
        {"virtual target", {r.virtual_target, p.virtual_target}},
        {"real target", {r.real_target, p.real_target}}};
    for (const auto& [what, v] : states)
      if (!(v.first == v.second)) return StateDifference{r.t, r.robot, what, v.first, v.second};
  }
  return std::nullopt;
}

}  // namespace covsim
