#include "sim/coverage_run.hpp"

#include <algorithm>

#include "scenarios/scenario_error.hpp"
#include "sim/simulation.hpp"

namespace covsim {

double settling_time(const std::vector<std::pair<double, double>>& series, double fraction) {
  if (series.empty()) return 0.0;
  const double limit = (1.0 + fraction) * series.back().second;
  double t = series.back().first;
  for (auto it = series.rbegin(); it != series.rend() && it->second <= limit; ++it)
    t = it->first;
  return t;
}

double ratio_to_best(const std::vector<std::pair<double, double>>& series, double last) {
  double best = last;
  for (const auto& [t, v] : series)
    best = std::min(best, v);
  return best > 0.0 ? last / best : 1.0;
}

CoverageOutcome run_coverage(const Scenario& scenario, CoverageObserver* observer, TraceSink* trace,
                             const PlannerMaker& make_planner) {
  Simulation sim(scenario, std::nullopt, make_planner, trace);
  if (observer != nullptr) sim.add_observer(observer);
  return sim.run();
}

}  // namespace covsim
