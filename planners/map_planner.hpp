#pragma once
// What the map-based planners (visibility graph, grid A*) share: they know Ω, plan a whole
// path when the goal changes, and follow it. A goal outside Ω is replaced by the closest
// point of Ω in the robot's component, and arriving there reports `projected`; no path
// reports `stalled`.
#include <optional>

#include "geometry/environment.hpp"
#include "planners/path_follower.hpp"
#include "planners/planner.hpp"

namespace covsim {

class MapPlanner : public Planner {
 public:
  void set_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;

 protected:
  explicit MapPlanner(const Environment& env) : env_(env) {}
  // A path from start to goal (both in Ω), start first; nullopt if there is none.
  virtual std::optional<std::vector<Vec2>> plan(Vec2 start, Vec2 goal) = 0;
  const Environment& env_;

 private:
  Vec2 goal_;
  bool planned_ = false;
  PlanStatus status_ = PlanStatus::reached, arrival_ = PlanStatus::reached;
  PathFollower follower_;
};

}  // namespace covsim
