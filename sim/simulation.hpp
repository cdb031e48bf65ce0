#pragma once
// One run of a scenario, under the caller's control: event by event (step), up to a time
// (run_until), or to its end (run), which is what run_coverage and `covsim run` do. However
// it is driven, the same scenario and seed give the same events and the same fingerprint.
// The run ends when it converges, a planner fails, every robot is stuck, or at max_time.
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/coverage_run.hpp"
#include "sim/timed_planner.hpp"

namespace covsim {

class Simulation {
 public:
  // seed, if given, replaces the scenario's; make_planner, if given, builds each robot's
  // planner. Throws ScenarioError for a scenario without robots or seed.
  explicit Simulation(const Scenario& scenario, std::optional<std::uint64_t> seed = {},
                      const PlannerMaker& make_planner = {}, TraceSink* trace = nullptr);
  ~Simulation();

  // Observers see every motion and sample; add them before the first step.
  void add_observer(CoverageObserver* o);
  // Dispatches one event; false once the run has ended (no event is then dispatched). An
  // exception from a component (a ComponentError, naming it) ends the simulation: every
  // later step, run_until or run throws std::logic_error saying so.
  bool step();
  // Runs to time t (clamped to max_time) or to the end of the run, whichever comes first.
  void run_until(SimTime t);
  // Runs to the end; the outcome.
  CoverageOutcome run();

  bool finished() const { return finished_; }
  // The error that stopped the simulation, if one did.
  const std::optional<std::string>& failure() const { return failed_; }
  SimTime now() const { return kernel_->now(); }
  SimTime max_time() const { return scenario_.coverage.max_time; }
  std::uint64_t fingerprint() const { return kernel_->fingerprint().value(); }
  std::uint64_t events() const { return kernel_->events_dispatched(); }
  const Scenario& scenario() const { return scenario_; }
  const CoverageController& controller() const { return *controller_; }
  // The outcome as final.json would record it now (a run not finished has stop reason
  // "running").
  CoverageOutcome outcome() const;
  // With the "external" coverage law: robot i's next target (taken at its next loop 1).
  // Throws std::logic_error with any other law.
  void set_target(std::uint32_t robot, Vec2 target);

 private:
  class Observers;
  void finish();
  // Starts the run if needed and runs f, recording an exception that escapes it.
  template <class F>
  void guarded(F&& f);

  Scenario scenario_;
  std::unique_ptr<Kernel> kernel_;
  PlannerTotals planner_totals_;
  std::unique_ptr<Observers> observers_;
  std::unique_ptr<CoverageController> controller_;
  PlannerMaker make_planner_;
  // Robots that do not know Ω (mapping.compare_known): the final real cost of the same run
  // with Ω known, from the same starts and seed (NaN: not run).
  double cost_known_ = NAN;
  bool started_ = false;
  bool finished_ = false;
  std::optional<std::string> failed_;
};

}  // namespace covsim
