#include "sim/simulation.hpp"

#include "sim/provenance.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/trace.hpp"
#include "io/interrupt.hpp"
#include "robot/external_law.hpp"
#include "robot/mapping.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim {

// Passes every hook to the observers in turn, and samples the real cost for the
// convergence measures.
class Simulation::Observers final : public CoverageObserver {
 public:
  void on_motion(SimTime t, const Robot& r) override {
    for (CoverageObserver* o : list)
      o->on_motion(t, r);
  }
  void on_sample(SimTime t, const CoverageController& c) override {
    series.emplace_back(t.seconds(), c.real_partition().cost());
    for (CoverageObserver* o : list)
      o->on_sample(t, c);
  }
  void on_finish(SimTime t, const CoverageController& c) override {
    if (series.empty() || series.back().first < t.seconds())
      series.emplace_back(t.seconds(), c.real_partition().cost());
    for (CoverageObserver* o : list)
      o->on_finish(t, c);
  }
  std::vector<CoverageObserver*> list;
  std::vector<std::pair<double, double>> series;
};

Simulation::Simulation(const Scenario& scenario, std::optional<std::uint64_t> seed,
                       const PlannerMaker& make_planner, TraceSink* trace)
    : scenario_(scenario), observers_(std::make_unique<Observers>()), make_planner_(make_planner) {
  if (seed) scenario_ = with_seed(scenario_, *seed);  // redraws what the seed draws
  if (scenario_.robot_positions.empty()) {
    throw ScenarioError(scenario_.source +
                        ": $: missing required key \"robots\" (a run needs robots)");
  }
  if (!scenario_.seed)
    throw ScenarioError(scenario_.source +
                        ": $: missing required key \"seed\" (a run needs a seed)");
  kernel_ = std::make_unique<Kernel>(*scenario_.seed);
  if (trace != nullptr) kernel_->attach_trace(trace);
  // Every planner (the scenario's, built by the controller for the free space of the robots'
  // bodies and told what they sense, or make_planner's) is wrapped to time its steps (wall
  // clock, outside the simulation).
  controller_ = std::make_unique<CoverageController>(
      *kernel_, *scenario_.environment, *scenario_.density, scenario_.robot_positions,
      scenario_.coverage, make_planner,
      [this](std::unique_ptr<Planner> p) -> std::unique_ptr<Planner> {
        return std::make_unique<TimedPlanner>(std::move(p), planner_totals_);
      });
  controller_->set_observer(observers_.get());
}

Simulation::~Simulation() = default;

void Simulation::add_observer(CoverageObserver* o) {
  observers_->list.push_back(o);
}

void Simulation::finish() {
  finished_ = true;
  observers_->on_finish(kernel_->now(), *controller_);
  const MappingConfig& m = scenario_.coverage.mapping;
  if (m.unknown() && m.compare_known) {
    // The reference for mapping.cost_ratio: the same robots, starts and seed, Ω known.
    Scenario known = scenario_;
    known.coverage.mapping = MappingConfig{};
    cost_known_ = Simulation(known, std::nullopt, make_planner_).run().cost_real;
  }
}

template <class F>
void Simulation::guarded(F&& f) {
  if (failed_) {
    throw std::logic_error("the simulation stopped on an error and cannot go on (" + *failed_ +
                           "): make a new one");
  }
  try {
    if (!started_) {
      controller_->start();
      started_ = true;
    }
    f();
  } catch (const Interrupted&) {
    throw;  // between events: the state is whole, the run may go on
  } catch (const std::exception& e) {
    failed_ = e.what();  // a handler stopped half-way: its state is not to be trusted
    throw;
  }
}

bool Simulation::step() {
  if (finished_) return false;
  guarded([&] {
    const RunResult r = kernel_->run_until(max_time(), 1);
    if (r.reason != StopReason::event_limit) finish();
  });
  return !finished_;
}

void Simulation::run_until(SimTime t) {
  if (finished_) return;
  guarded([&] {
    const SimTime until = std::min(t, max_time());
    if (until < kernel_->now()) return;
    const RunResult r = kernel_->run_until(until);
    if (r.reason == StopReason::stopped || r.reason == StopReason::queue_empty ||
        until == max_time())
      finish();
  });
}

CoverageOutcome Simulation::run() {
  run_until(max_time());
  return outcome();
}

void Simulation::set_target(std::uint32_t robot, Vec2 target) {
  auto* law = dynamic_cast<ExternalLaw*>(&controller_->law());
  if (law == nullptr)
    throw std::logic_error("set_target needs the \"external\" coverage law (controller.type)");
  if (robot >= controller_->robots().size())
    throw std::out_of_range("set_target: no robot " + std::to_string(robot));
  law->set_target(robot, target);
}

CoverageOutcome Simulation::outcome() const {
  const CoverageController& c = *controller_;
  CoverageOutcome out;
  out.scenario = scenario_.source;
  out.provenance = this_build();
  out.converged = c.converged();
  out.sim_time = kernel_->now();
  out.planner_failure = c.planner_failure();
  out.left_environment = c.left_environment();
  out.stop_reason = !finished_             ? "running"
                    : out.converged        ? "converged"
                    : out.planner_failure  ? "planner_failure"
                    : out.left_environment ? "left_environment"
                    : c.stuck()            ? "stuck"
                                           : "max_time";
  out.events = kernel_->events_dispatched();
  out.seed = *scenario_.seed;
  const VoronoiPartition& last = c.real_partition();
  for (const Robot& r : c.robots()) {
    out.robots.push_back(RobotOutcome{r.position, r.virtual_generator, r.virtual_target,
                                      r.real_target, r.projected, r.status, r.path_length,
                                      r.target_outside_steps, r.stalled_time,
                                      distance(r.position, last.summary(r.id).centroid)});
  }
  // Algorithm 1, line 8: the last partition, of the real positions.
  const VoronoiPartition& virtual_partition = c.virtual_partition();
  out.cost_virtual = virtual_partition.cost();
  out.cost_real_in_virtual_partition = virtual_partition.cost(c.positions());
  out.cost_real = last.cost();
  out.decentralized = c.decentralized();
  out.network = c.network_totals(true);
  out.fingerprint = kernel_->fingerprint().value();
  const auto& series = observers_->series;
  out.time_to_10_percent = settling_time(series, 0.10);
  out.time_to_5_percent = settling_time(series, 0.05);
  out.time_to_1_percent = settling_time(series, 0.01);
  out.cost_to_best = ratio_to_best(series, out.cost_real);
  for (const RobotOutcome& r : out.robots) {
    out.path_length += r.path_length;
    out.target_outside_steps += r.target_outside_steps;
    out.stalled_time += r.stalled_time;
    out.centroid_distance_mean += r.centroid_distance / static_cast<double>(out.robots.size());
    out.centroid_distance_max = std::max(out.centroid_distance_max, r.centroid_distance);
  }
  out.radius = c.config().radius;
  out.body_gap_min = c.body_gap_min();
  out.contact_time = c.contact_time();
  out.wall_contacts = c.wall_contacts();
  out.deadlocks = c.deadlocks();
  out.deadlock_time = c.deadlock_time();
  out.deadlocks_resolved = c.deadlocks_resolved();
  out.turn_time = c.turn_time();
  out.hard_stops = c.hard_stops();
  out.localization_error_mean = c.localization_error_mean();
  out.localization_error_max = c.localization_error_max();
  out.fixes = c.fixes();
  if (c.config().mode == LoopMode::periodic)
    out.loop_ratio = c.config().loop1_period.seconds() / c.config().loop2_period.seconds();
  if (const Mapping* m = c.mapping()) {
    out.known = std::string(to_string(c.config().mapping.known));
    out.known_fraction = m->known_fraction();
    out.known_fraction_min = 1.0;
    for (std::uint32_t i = 0; i < c.robots().size(); ++i)
      out.known_fraction_min = std::min(out.known_fraction_min, m->known_fraction(i));
    out.mapping_time_90 = m->time_to_90() ? m->time_to_90()->seconds() : NAN;
    out.mapping_time_100 = m->time_to_100() ? m->time_to_100()->seconds() : NAN;
    out.map_disagreement = m->disagreement();
    out.map_bytes = m->bytes_sent();
    out.map_bytes_new = m->new_bytes_sent();
    out.scans = m->scans().size();
    out.obstacles_known_min = m->elements_known_min();
    out.obstacles = m->elements();
    out.cost_known = cost_known_;
    out.map_model = m->grid() ? "occupancy" : "polygons";
    if (m->grid()) {
      const Mapping::MapErrors e = m->errors();
      out.map_false_occupied = e.false_occupied;
      out.map_false_free = e.false_free;
    }
    out.discoveries = c.discoveries();
  }
  out.planner_seconds = planner_totals_.seconds;
  out.planner_steps = planner_totals_.steps;
  return out;
}

}  // namespace covsim
