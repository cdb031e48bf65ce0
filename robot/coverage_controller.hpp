#pragma once
// The paper's non-convex coverage controller (Breitenmoser et al. 2010, Algorithms 1 and 2)
// on the event kernel: a thin scheduler of loop 1, loop 2 and the check over swappable
// parts, as ns-3's Simulator forwards to its implementation.
//
// - The coverage law (coverage_law.hpp) turns what a robot knows into its next target.
// - The neighbour view (ideal_view.hpp, networked_view.hpp) says what a robot knows of the
//   others.
// - The belief layer (belief_layer.hpp) says where a robot believes it is and what it
//   believes Ω is (its localization, its map).
// - The sensor model (sensor_model.hpp) says what its planner senses.
// - The planning layer (planning_layer.hpp) drives its planner (planners/) on that belief.
// - The motion layer (motion_layer.hpp) carries the planner's steps out: kinematics,
//   collision avoidance, deadlocks, giving way.
// - The body checks (body_checks.hpp) measure the bodies' gaps and contacts.
// The controller keeps loop 1, loop 2 and the check, and composes the layers.
// Metrics are observers in sim/ that read the controller's const state.
//
// Loop 1 (event "loop1", class 0), for robot i once its view is ready: the law's target
// becomes the virtual target; outside Ω (an obstacle boundary Voronoi region) the real target
// is its projection, the closest point of Ω, else the virtual target itself. The planner is
// handed the virtual target (projection policy `discover`, the paper's: TangentBug reaches it
// or finds it unreachable and settles at its projection) or the real target (`known`: Ω is
// known, so the projection is the goal from the start), only when that goal has moved (by
// more than the position tolerance): a goal it has reached, found unreachable or given up on
// is never handed to it again, and its budgets are per goal.
// Loop 2 (event "loop2", class 2, every loop2_period): a planner step toward the goal in the
// real world, and, for a law with virtual generators, a straight step of the virtual
// generator toward the virtual target as if there were no obstacles; both at most
// max_speed * loop2_period. In classic mode a robot that has settled runs loop 1 again at the
// next tick; in periodic mode loop 1 runs every loop1_period. Each tick ends with a check
// (class 6) that folds all positions into the fingerprint and stops the run when every robot
// is stable, or (stuck) when every robot not stable has stalled short of an unchanged target.
// A planner that stalls while its target lies outside Ω is sent to the projection instead;
// one that reports `projected` for a goal inside Ω stops the run (planner_failure()). The
// world stops a motion at the wall it would cross (Environment::advance), except for a
// planner that does not avoid obstacles (the `none` baseline): its motion into an obstacle
// (ending in one, or cutting through one deeper than the position tolerance) stops the run
// where it crosses ∂Ω (left_environment()). A
// motion that still leaves Ω is an internal error: it throws.
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "core/kernel.hpp"
#include "geometry/configuration_space.hpp"
#include "robot/belief_layer.hpp"
#include "robot/body_checks.hpp"
#include "robot/coverage_config.hpp"
#include "robot/generator_state.hpp"
#include "robot/motion_layer.hpp"
#include "robot/neighbor_view.hpp"
#include "robot/planner_space.hpp"
#include "robot/planning_layer.hpp"
#include "robot/robot.hpp"
#include "robot/sensor_model.hpp"

namespace covsim {

class CoverageController;
class Mapping;

// What stopped a run at once, and where: a robot, the time, its goal and its position.
struct RobotIncident {
  std::uint32_t robot = 0;
  SimTime time;
  Vec2 goal, position;
};
// A planner that contradicts the environment: it declared a goal inside Ω unreachable
// (TangentBug's promise, on which the paper's Lemma 2 rests, is broken).
using PlannerFailure = RobotIncident;
// A robot without a planner that avoids obstacles drove out of Ω (the paper's Fig. 2d): its
// position is where it crossed ∂Ω.
using LeftEnvironment = RobotIncident;

// Hooks for recording a run; they read the controller's const state.
class CoverageObserver {
 public:
  virtual ~CoverageObserver() = default;
  virtual void on_motion(SimTime, const Robot&) {}               // after each loop-2 step
  virtual void on_sample(SimTime, const CoverageController&) {}  // every sample_period
  virtual void on_finish(SimTime, const CoverageController&) {}  // once, when the run ends
};

// Builds robot i's planner; unset, the planner the configuration names.
using PlannerMaker = std::function<std::unique_ptr<Planner>(std::uint32_t robot)>;
// Wraps each robot's planner, however it was built (a timer around its steps).
using PlannerWrapper = std::function<std::unique_ptr<Planner>(std::unique_ptr<Planner>)>;

class CoverageController {
 public:
  CoverageController(Kernel& kernel, const Environment& env, const Density& density,
                     const std::vector<Vec2>& starts, CoverageConfig config,
                     const PlannerMaker& make_planner = {}, const PlannerWrapper& wrap = {});
  ~CoverageController();

  void set_observer(CoverageObserver* o) { observer_ = o; }
  // Schedules loop 1 and loop 2 for every robot, the samples and the checks.
  void start();
  bool converged() const { return converged_; }
  // The run stopped with robots stalled short of targets that no longer change.
  bool stuck() const { return stuck_; }
  const std::optional<PlannerFailure>& planner_failure() const { return failure_; }
  const std::optional<LeftEnvironment>& left_environment() const { return departure_; }

  const std::vector<Robot>& robots() const { return robots_; }
  const CoverageConfig& config() const { return config_; }
  const Environment& environment() const { return env_; }
  // Where robot centres may go (Ω ⊖ radius), and the part of it robot i plans, senses and
  // moves in.
  const ConfigurationSpace& configuration_space() const { return *space_; }
  const Environment& free_space(std::uint32_t i) const { return space_->part(part_[i]); }
  // Where robot i's planner plans: its free space, or, for a map planner beside a
  // localization, that shrunk further by the inflation.
  const Environment& planner_space(std::uint32_t i) const { return planner_space_->of(i); }
  // With bodies (radius > 0): the least distance between two robots' bodies over the run's
  // motion steps (negative: they overlapped; NaN for points), robot-seconds spent with a
  // body overlapping another, and motion steps that ended with a body overlapping a wall.
  double body_gap_min() const { return bodies_ ? bodies_->gap_min() : NAN; }
  double contact_time() const { return bodies_ ? bodies_->contact_time() : 0.0; }
  std::uint64_t wall_contacts() const { return bodies_ ? bodies_->wall_contacts() : 0; }
  // With collision avoidance: deadlocks (a robot blocked short of its planner's step by its
  // neighbours, making good a tenth of the way or less, for kDeadlockTime or longer; one lasts
  // until the robot reaches a planner step again), the robot-seconds they lasted, and how many
  // of them ended before the run did.
  static constexpr double kDeadlockTime = MotionLayer::kDeadlockTime;  // s
  std::uint64_t deadlocks() const { return motion_->deadlocks(); }
  double deadlock_time() const { return motion_->deadlock_time(); }
  std::uint64_t deadlocks_resolved() const { return motion_->deadlocks_resolved(); }
  // Times a robot stepped aside to let another by.
  std::uint64_t give_ways() const { return motion_->give_ways(); }
  // With kinematics: robot-seconds spent turning in place, and stops harder than the
  // acceleration limit (a detour moved the point a body was driving to).
  double turn_time() const { return motion_->turn_time(); }
  std::uint64_t hard_stops() const { return motion_->hard_stops(); }
  // With a localization other than exact: the mean and the largest distance between a
  // robot's estimate and its position over every loop-2 step of every robot, and the
  // tracking fixes delivered.
  double localization_error_mean() const { return belief_->localization_error_mean(); }
  double localization_error_max() const { return belief_->localization_error_max(); }
  std::uint64_t fixes() const { return belief_->fixes(); }
  const CellIntegrator& integrator() const { return integrator_; }
  // Robots that do not know Ω: their maps; null when they know it.
  const Mapping* mapping() const { return belief_->mapping(); }
  // Times a robot that maps Ω found unreachable a goal its map placed in free space.
  std::uint64_t discoveries() const { return belief_->discoveries(); }
  const CoverageLaw& law() const { return *law_; }
  CoverageLaw& law() { return *law_; }
  const NeighborView& view() const { return *view_; }
  bool decentralized() const { return view_->decentralized(); }
  NetworkTotals network_totals(bool radio = false) const { return view_->totals(radio); }
  SimTime now() const { return kernel_.now(); }
  const Tolerances& tolerances() const { return tol_; }
  // Every robot's virtual generator and position now, and their partitions (computed once
  // per change; robots at one place split their cell).
  const GeneratorState& generators() const { return *state_; }
  const std::vector<Vec2>& positions() const { return state_->points(Generators::positions); }
  const std::vector<Vec2>& virtual_generators() const {
    return state_->points(Generators::virtual_generators);
  }
  const VoronoiPartition& virtual_partition() const {
    return state_->partition(Generators::virtual_generators);
  }
  const VoronoiPartition& real_partition() const {
    return state_->partition(Generators::positions);
  }

 private:
  void loop1(std::uint32_t i);
  // The goal loop 1 hands robot r's planner under the projection policy.
  Vec2 planner_goal(const Robot& r) const;
  // How deep a straight motion between p and q, both in Ω, runs outside Ω (0 if it stays in).
  double excursion(const Environment& space, Vec2 p, Vec2 q) const;
  void loop2(Kernel& k, std::uint32_t i);
  void check(Kernel& k);
  void move_to(Robot& r, Vec2 next);
  // The robot is at its planner's step, which ended with this status; false: the run stops.
  bool arrive(Kernel& k, Robot& r, PlanStatus status);

  Kernel& kernel_;
  const Environment& env_;
  std::unique_ptr<ConfigurationSpace> space_;
  std::vector<std::size_t> part_;  // robot i's part of space_
  std::unique_ptr<PlannerSpace> planner_space_;
  std::unique_ptr<BeliefLayer> belief_;
  std::unique_ptr<PlanningLayer> planning_;
  std::unique_ptr<MotionLayer> motion_;
  std::unique_ptr<BodyChecks> bodies_;  // unset: robots without bodies
  CellIntegrator integrator_;
  CoverageConfig config_;
  Tolerances tol_;
  double step_;
  std::vector<Robot> robots_;
  std::unique_ptr<GeneratorState> state_;
  std::unique_ptr<CoverageLaw> law_;
  std::unique_ptr<NeighborView> view_;
  std::unique_ptr<SensorModel> sensor_;
  CoverageObserver* observer_ = nullptr;
  EventKind loop1_kind_ = 0, loop2_kind_ = 0, sample_kind_ = 0, check_kind_ = 0;
  bool converged_ = false;
  bool stuck_ = false;
  std::optional<PlannerFailure> failure_;
  std::optional<LeftEnvironment> departure_;
};

}  // namespace covsim
