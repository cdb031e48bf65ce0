#pragma once
// Wall-clock time spent in planner steps, measured by wrapping each robot's planner: it varies
// between runs and machines, so it is kept out of the simulation and its fingerprint.
#include <chrono>
#include <memory>

#include "planners/planner.hpp"

namespace covsim {

struct PlannerTotals {
  double seconds = 0.0;
  std::uint64_t steps = 0;
  // Mean wall-clock microseconds per planner step (0 without steps).
  double step_time_us() const {
    return steps > 0 ? 1e6 * seconds / static_cast<double>(steps) : 0.0;
  }
};

class TimedPlanner final : public Planner {
 public:
  TimedPlanner(std::unique_ptr<Planner> inner, PlannerTotals& totals)
      : inner_(std::move(inner)), totals_(totals) {}
  std::string_view name() const override { return inner_->name(); }
  void set_goal(Vec2 goal) override { inner_->set_goal(goal); }
  void move_goal(Vec2 goal) override { inner_->move_goal(goal); }
  bool avoids_obstacles() const override { return inner_->avoids_obstacles(); }
  PlannerPicture picture() const override { return inner_->picture(); }
  void learn(const std::vector<SensedPiece>& walls) override { inner_->learn(walls); }
  PlanStep step(const SensorReading& reading, double max_step) override {
    const auto started = std::chrono::steady_clock::now();
    const PlanStep s = inner_->step(reading, max_step);
    totals_.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    ++totals_.steps;
    return s;
  }
  const Planner& inner() const { return *inner_; }

 private:
  std::unique_ptr<Planner> inner_;
  PlannerTotals& totals_;
};

}  // namespace covsim
