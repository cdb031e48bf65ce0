#include "analysis/coverage_run.hpp"

#include <algorithm>

#include "analysis/timed_planner.hpp"
#include "core/trace.hpp"
#include "planners/planner_registry.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim {

namespace {
// Samples the real cost for the convergence measures and passes everything on.
class CostSampler final : public CoverageObserver {
 public:
  explicit CostSampler(CoverageObserver* next) : next_(next) {}
  void on_motion(SimTime t, const Robot& r) override {
    if (next_ != nullptr) next_->on_motion(t, r);
  }
  void on_sample(SimTime t, const CoverageController& c) override {
    series.emplace_back(t.seconds(), c.real_partition().cost());
    if (next_ != nullptr) next_->on_sample(t, c);
  }
  void on_finish(SimTime t, const CoverageController& c) override {
    if (series.empty() || series.back().first < t.seconds())
      series.emplace_back(t.seconds(), c.real_partition().cost());
    if (next_ != nullptr) next_->on_finish(t, c);
  }
  std::vector<std::pair<double, double>> series;

 private:
  CoverageObserver* next_;
};
}  // namespace

double settling_time(const std::vector<std::pair<double, double>>& series, double fraction) {
  if (series.empty()) return 0.0;
  const double limit = (1.0 + fraction) * series.back().second;
  double t = series.back().first;
  for (auto it = series.rbegin(); it != series.rend() && it->second <= limit; ++it)
    t = it->first;
  return t;
}

CoverageOutcome run_coverage(const Scenario& scenario, CoverageObserver* observer, TraceSink* trace,
                             const PlannerMaker& make_planner) {
  if (scenario.robot_positions.empty()) {
    throw ScenarioError(scenario.source +
                        ": $: missing required key \"robots\" (a run needs robots)");
  }
  if (!scenario.seed)
    throw ScenarioError(scenario.source +
                        ": $: missing required key \"seed\" (a run needs a seed)");
  Kernel kernel(*scenario.seed);
  if (trace != nullptr) kernel.attach_trace(trace);
  // Every planner is wrapped to time its steps (wall clock, outside the simulation).
  PlannerTotals planner_totals;
  const PlannerSource source =
      make_planner
          ? PlannerSource{}
          : planner_source(scenario.coverage.planner,
                           PlannerContext{*scenario.environment,
                                          SensorSpec{scenario.coverage.sensor.noise_sigma}});
  CoverageController controller(kernel, *scenario.environment, *scenario.density,
                                scenario.robot_positions, scenario.coverage,
                                [&](std::uint32_t i) -> std::unique_ptr<Planner> {
                                  return std::make_unique<TimedPlanner>(
                                      make_planner ? make_planner(i) : source(), planner_totals);
                                });
  CostSampler sampler(observer);
  controller.set_observer(&sampler);
  controller.start();
  kernel.run_until(scenario.coverage.max_time);
  sampler.on_finish(kernel.now(), controller);

  CoverageOutcome out;
  out.scenario = scenario.source;
  out.converged = controller.converged();
  out.sim_time = kernel.now();
  out.planner_failure = controller.planner_failure();
  out.stop_reason = out.converged         ? "converged"
                    : out.planner_failure ? "planner_failure"
                    : controller.stuck()  ? "stuck"
                                          : "max_time";
  out.events = kernel.events_dispatched();
  out.seed = *scenario.seed;
  const VoronoiPartition& last = controller.real_partition();
  for (const Robot& r : controller.robots()) {
    out.robots.push_back(RobotOutcome{r.position, r.virtual_generator, r.virtual_target,
                                      r.real_target, r.projected, r.status, r.path_length,
                                      r.target_outside_steps, r.stalled_time,
                                      distance(r.position, last.summary(r.id).centroid)});
  }
  // Algorithm 1, line 8: the last partition, of the real positions.
  const VoronoiPartition& virtual_partition = controller.virtual_partition();
  out.cost_virtual = virtual_partition.cost();
  const std::vector<Vec2> real = controller.positions();
  out.cost_real_in_virtual_partition = virtual_partition.cost(real);
  out.cost_real = controller.real_partition().cost();
  out.decentralized = controller.decentralized();
  out.network = controller.network_totals();
  out.fingerprint = kernel.fingerprint().value();
  out.time_to_10_percent = settling_time(sampler.series, 0.10);
  out.time_to_5_percent = settling_time(sampler.series, 0.05);
  out.time_to_1_percent = settling_time(sampler.series, 0.01);
  for (const RobotOutcome& r : out.robots) {
    out.path_length += r.path_length;
    out.target_outside_steps += r.target_outside_steps;
    out.stalled_time += r.stalled_time;
    out.centroid_distance_mean += r.centroid_distance / static_cast<double>(out.robots.size());
    out.centroid_distance_max = std::max(out.centroid_distance_max, r.centroid_distance);
  }
  out.planner_seconds = planner_totals.seconds;
  out.planner_steps = planner_totals.steps;
  return out;
}

}  // namespace covsim
