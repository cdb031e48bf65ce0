#pragma once
// A planner that declares every goal unreachable at once: a broken promise, for the tests of
// what a run and its records do about it.
#include <string_view>

#include "planners/planner.hpp"

namespace covsim::test {

class GivesUp final : public Planner {
 public:
  std::string_view name() const override { return "gives_up"; }
  void set_goal(Vec2) override {}
  PlanStep step(const SensorReading& r, double) override {
    return {r.position, PlanStatus::projected};
  }
};

}  // namespace covsim::test
