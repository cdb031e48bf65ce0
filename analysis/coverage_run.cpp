#include "analysis/coverage_run.hpp"

#include "core/trace.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim {

CoverageOutcome run_coverage(const Scenario& scenario, CoverageObserver* observer,
                             TraceSink* trace) {
  if (scenario.robot_positions.empty()) {
    throw ScenarioError(scenario.source +
                        ": $: missing required key \"robots\" (a run needs robots)");
  }
  if (!scenario.seed)
    throw ScenarioError(scenario.source +
                        ": $: missing required key \"seed\" (a run needs a seed)");
  Kernel kernel(*scenario.seed);
  if (trace != nullptr) kernel.attach_trace(trace);
  CoverageController controller(kernel, *scenario.environment, *scenario.density,
                                scenario.robot_positions, scenario.coverage);
  controller.set_observer(observer);
  controller.start();
  kernel.run_until(scenario.coverage.max_time);
  if (observer != nullptr) observer->on_finish(kernel.now(), controller);

  CoverageOutcome out;
  out.converged = controller.converged();
  out.sim_time = kernel.now();
  out.stop_reason = out.converged ? "converged" : "max_time";
  out.events = kernel.events_dispatched();
  out.seed = *scenario.seed;
  for (const Robot& r : controller.robots()) {
    out.robots.push_back(RobotOutcome{r.position, r.virtual_generator, r.virtual_target,
                                      r.real_target, r.projected, r.status, r.path_length});
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
  return out;
}

}  // namespace covsim
