#pragma once
// The registry of planners: a scenario's "planner": {"type": NAME, ...} names one.
#include "planners/planner_entry.hpp"

namespace covsim {

Registry<PlannerEntry>& planner_registry();

// The source of a run's planners; unknown types throw std::invalid_argument naming the
// registered ones.
PlannerSource planner_source(const PlannerConfig& config, const PlannerContext& context);
// One planner of the given type with its default parameters (tests, benchmarks, scripts).
std::unique_ptr<Planner> make_planner(std::string_view type, const Environment& env,
                                      const SensorSpec& sensor = {});

}  // namespace covsim
