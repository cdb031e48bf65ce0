#pragma once
// Keeps a run's PlannerMapRecord as it goes: at each sample (and at the end) the walls each
// planner's map gained since the last, once per map (the planners of a centralized run share
// one), and each robot's way ahead when it changed.
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "analysis/records/planner_map_record.hpp"
#include "robot/robot.hpp"

namespace covsim {

class PlannerMapLog {
 public:
  void record(double t, const std::vector<Robot>& robots);
  const PlannerMapRecord& record() const { return record_; }

 private:
  PlannerMapRecord record_;
  // Per map, its walls as last recorded; per robot, its way as last recorded.
  std::unordered_map<const void*, std::vector<std::pair<Vec2, Vec2>>> walls_;
  std::vector<std::optional<std::vector<Vec2>>> ways_;
};

}  // namespace covsim
