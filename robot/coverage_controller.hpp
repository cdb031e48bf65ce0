#pragma once
// The paper's non-convex coverage controller (Breitenmoser et al. 2010, Algorithms 1 and 2)
// on the event kernel: a thin scheduler of loop 1, loop 2 and the check over swappable
// parts, as ns-3's Simulator forwards to its implementation.
//
// - The coverage law (coverage_law.hpp) turns what a robot knows into its next target.
// - The neighbour view (ideal_view.hpp, networked_view.hpp) says what a robot knows.
// - The sensor model (sensor_model.hpp) says what its planner senses.
// - The planner (planners/) moves it.
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
#include "robot/collision_avoidance.hpp"
#include "robot/coverage_config.hpp"
#include "robot/generator_state.hpp"
#include "robot/localization.hpp"
#include "robot/neighbor_view.hpp"
#include "robot/robot.hpp"
#include "robot/sensor_model.hpp"

namespace covsim {

class CoverageController;
class Mapping;
struct Scan;
class ReceiverGrid;

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
  // With bodies (radius > 0): the least distance between two robots' bodies over the run's
  // motion steps (negative: they overlapped; NaN for points), robot-seconds spent with a
  // body overlapping another, and motion steps that ended with a body overlapping a wall.
  double body_gap_min() const { return body_gap_min_; }
  double contact_time() const { return contact_time_; }
  std::uint64_t wall_contacts() const { return wall_contacts_; }
  // With collision avoidance: deadlocks (a robot blocked short of its planner's step by its
  // neighbours, making good a tenth of the way or less, for kDeadlockTime or longer; one lasts
  // until the robot reaches a planner step again), the robot-seconds they lasted, and how many
  // of them ended before the run did.
  static constexpr double kDeadlockTime = 1.0;  // s
  std::uint64_t deadlocks() const { return deadlocks_; }
  double deadlock_time() const { return deadlock_time_; }
  std::uint64_t deadlocks_resolved() const { return deadlocks_resolved_; }
  // Times a robot stepped aside to let another by.
  std::uint64_t give_ways() const { return give_ways_; }
  // With kinematics: robot-seconds spent turning in place, and stops harder than the
  // acceleration limit (a detour moved the point a body was driving to).
  double turn_time() const { return turn_time_; }
  std::uint64_t hard_stops() const { return hard_stops_; }
  // With a localization other than exact: the mean and the largest distance between a
  // robot's estimate and its position over every loop-2 step of
  // every robot, and the tracking fixes delivered.
  double localization_error_mean() const {
    return localization_steps_ == 0
               ? 0.0
               : localization_error_sum_ / static_cast<double>(localization_steps_);
  }
  double localization_error_max() const { return localization_error_max_; }
  std::uint64_t fixes() const { return localization_ ? localization_->fixes() : 0; }
  const CellIntegrator& integrator() const { return integrator_; }
  // Robots that do not know Ω: their maps; null when they know it.
  const Mapping* mapping() const { return mapping_.get(); }
  // Times a robot that maps Ω found unreachable a goal its map placed in free space.
  std::uint64_t discoveries() const { return discoveries_; }
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
  // Runs f, a call into robot i's component (role, name), turning what it throws into a
  // ComponentError naming the robot, the component and the time, the cause nested.
  template <class F>
  auto guarded(std::uint32_t i, std::string_view role, std::string_view name, F&& f);
  void loop1(std::uint32_t i);
  // Robot i heard a neighbour's reading its map did not hold: its planner takes the walls.
  void learn(std::uint32_t i, const Scan& scan);
  // What robot i knows, for a robot that maps Ω: its cells in its belief (the integrator),
  // from a partition shared per belief when it knows every generator as it is now.
  void believe(Knowledge& k, const CellIntegrator& integrator);
  // The goal loop 1 hands robot r's planner under the projection policy.
  Vec2 planner_goal(const Robot& r) const;
  // How deep a straight motion between p and q, both in Ω, runs outside Ω (0 if it stays in).
  double excursion(const Environment& space, Vec2 p, Vec2 q) const;
  void set_goal(Robot& r, Vec2 goal);
  void loop2(Kernel& k, std::uint32_t i);
  void check(Kernel& k);
  // Body distances and contacts at a motion step (radius > 0).
  void check_bodies();
  // Robot r's planner's next step from where it is; throws for a step that is not finite or
  // longer than the step length.
  // With a localization the planner works in the odometry's frame: it is told the reading as
  // the robot maps it from where its odometry says it is, and its step is the same
  // displacement from where the robot is.
  PlanStep planner_step(const Kernel& k, Robot& r);
  // Where robot r believes it is: its localization's estimate, taken into its free space (it
  // knows it is not inside a wall); its position with exact localization.
  Vec2 known_position(const Robot& r);
  // Where robot r's planner believes it is: its odometry; its position with exact
  // localization.
  Vec2 planner_position(const Robot& r) const;
  // A point of Ω in the frame robot r's planner works in; a point of r's free space stays in
  // it (the map read in that frame).
  Vec2 in_planner_frame(Robot& r, Vec2 p);
  // How near its target a robot counts as there: the position tolerance, or, with a
  // localization, not nearer than three standard deviations of its estimate's jitter (it
  // cannot tell).
  double within_reach() const;
  // A goal in Ω for robot r's planner: a new one, or the one under way moved.
  void move_goal(Robot& r, Vec2 goal);
  // How near its planner's goal a robot counts as there by where its planner believes it is
  // (every motion, however short, drifts an odometry).
  double planner_reach() const;
  // The position tolerance, or kReachDeviations standard deviations (on each axis) of a
  // position's jitter if more: a 2D Gaussian jump goes beyond 3.5 of them with probability
  // exp(-3.5² / 2), 0.2%.
  static constexpr double kReachDeviations = 3.5;
  double reach(double sigma) const;
  void move_to(Robot& r, Vec2 next);
  // The robot is at its planner's step, which ended with this status; false: the run stops.
  bool arrive(Kernel& k, Robot& r, PlanStatus status);
  // Whether robot r's planner's goal lies outside the free space (its planner may find it
  // unreachable).
  bool unreachable(const Robot& r) const;
  // A motion step toward r's waypoint (with collision avoidance or kinematics); false: the
  // run stops.
  bool follow_waypoint(Kernel& k, Robot& r);
  bool arrive_at_waypoint(Kernel& k, Robot& r);
  // The body's motion toward `to` in one motion step (at once without kinematics): where it
  // gets to.
  Vec2 drive(Robot& r, Vec2 to);
  // Calls f with every robot that may lie within radius of p (a superset), in index order.
  template <class F>
  void for_each_near(Vec2 p, double radius, F&& f) const;
  // What robot r senses of its neighbours, into neighbors_.
  void sense_neighbors(const Robot& r);
  // The avoidance's velocity for robot r from what it senses; throws for one that is not
  // finite or faster than max_speed.
  Vec2 avoiding_velocity(const Robot& r, Vec2 preferred, double max_speed);
  // A robot deadlocked for a while: replanned, or one of the two in each other's way (the
  // larger id, or a settled robot on the waypoint) gives way.
  void resolve(Robot& r);
  // Robot r steps aside for a robot at `from`; false (and nothing started) when the walls and
  // the other bodies leave it no room.
  bool start_giving_way(Robot& r, Vec2 from);
  // A motion step aside for the robot it makes room for; then it returns to its goal.
  void give_way(Robot& r);
  // The largest fraction of the straight motion from r's position to `to` that brings its
  // body no nearer to another's than touching (or than it already is).
  double clear_fraction(const Robot& r, Vec2 to) const;

  Kernel& kernel_;
  const Environment& env_;
  std::unique_ptr<ConfigurationSpace> space_;
  std::vector<std::size_t> part_;  // robot i's part of space_
  double body_gap_min_ = NAN, contact_time_ = 0.0;
  std::uint64_t wall_contacts_ = 0;
  std::unique_ptr<CollisionAvoidance> avoidance_;  // unset: none
  std::unique_ptr<Kinematics> kinematics_;         // unset: the single integrator
  std::unique_ptr<Localization> localization_;     // unset: exact
  std::unique_ptr<Mapping> mapping_;               // unset: Ω known (environment.known full)
  std::uint64_t discoveries_ = 0;
  struct BelievedPartition {
    const CellIntegrator* integrator = nullptr;
    std::uint64_t version = 0;
    std::optional<VoronoiPartition> partition;
  };
  BelievedPartition believed_[2];  // of the virtual generators, of the positions
  SensorSpec sensing_;             // what the planners are told of their sensing and localization
  double localization_error_sum_ = 0.0, localization_error_max_ = 0.0;
  std::uint64_t localization_steps_ = 0;
  double turn_time_ = 0.0;
  std::uint64_t hard_stops_ = 0;
  std::vector<SensedNeighbor> neighbors_;
  std::unique_ptr<ReceiverGrid> near_;  // with avoidance: the robots near a point
  double near_range_ = 0.0;
  mutable std::vector<std::uint32_t> near_ids_;
  std::uint64_t deadlocks_ = 0, deadlocks_resolved_ = 0, give_ways_ = 0;
  double deadlock_time_ = 0.0;
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
