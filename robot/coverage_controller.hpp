#pragma once
// The paper's non-convex coverage controller (Breitenmoser et al. 2010, Algorithms 1 and 2)
// on the event kernel.
//
// Loop 1 (event "loop1", class 0), for robot i: the Voronoi cell of its virtual generator
// among the virtual generators, the centroid of the cell ∩ Ω becomes the virtual target; if
// that lies outside Ω (an obstacle boundary Voronoi region) the real target is its
// projection, the closest point of Ω, else the virtual target itself. The planner is given
// the virtual target: TangentBug reaches it, or finds it unreachable after one loop round
// the obstacle and settles at the projection.
// Loop 2 (event "loop2", class 1, every loop2_period): a planner step toward the real
// target, and a straight step of the virtual generator toward the virtual target as if
// there were no obstacles; both at most max_speed * loop2_period.
// In classic mode a robot that has settled runs loop 1 again at the next tick; in periodic
// mode loop 1 runs every loop1_period. A planner is given a new goal only when the target
// has moved (by more than the position tolerance): a goal it has reached, or found
// unreachable, is never handed to it again, and its budgets are per goal. Decentralized, a
// robot runs its first loop 1 only once it has heard its neighbours (NetworkConfig::acquire). Each
// tick ends with a check (class 3) that folds all positions into the fingerprint and stops the run
// when every robot is stable. A motion that would leave Ω is an internal error: it throws.
//
// The baseline controllers (ControllerKind) replace loop 1: euclidean_lloyd targets the
// centroid of the robot's own cell among the real positions, geodesic_lloyd the geodesic
// Lloyd step (GeodesicPartition); they have no virtual generators (virtual_generator
// follows the position) and converge when every robot has reached its target or settled at
// its projection. With any controller, a planner that stalls while its target lies outside
// Ω is sent to the target's projection instead (the target is treated as unreachable). A
// robot stalled with nothing left to change is stuck; when every robot is converged or
// stuck, the run stops (stuck()).

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/geometry/geodesic_partition.hpp"
#include "core/geometry/voronoi_partition.hpp"
#include "core/kernel.hpp"
#include "net/channel.hpp"
#include "net/comm_graph.hpp"
#include "net/neighbor_table.hpp"
#include "robot/coverage_config.hpp"
#include "robot/robot.hpp"

namespace covsim {

class CoverageController;

// Wall-clock time spent in planner steps (varies between runs; never in the fingerprint).
struct PlannerTotals {
  double seconds = 0.0;
  std::uint64_t steps = 0;
};

struct NetworkTotals {
  std::uint64_t sent = 0;  // link transmissions (one per receiver per broadcast)
  std::uint64_t delivered = 0;
  std::uint64_t lost = 0;         // dropped by the loss model
  std::uint64_t unreachable = 0;  // out of range or blocked by walls
};

// The state of information at one instant.
struct NetworkSample {
  double info_age_mean = 0.0, info_age_max = 0.0;  // seconds, over all table entries
  // Robots' own cells (each from its table) disagree: the area of Ω that no robot claims,
  // and the area claimed by two or more (estimated on a lattice of about 4000 points of Ω).
  double area_claimed_by_none = 0.0, area_claimed_by_several = 0.0;
  CommGraphMetrics graph;
};

// A planner that contradicts the environment: it declared a goal inside Ω unreachable. The
// run stops at once (TangentBug's promise, on which the paper's Lemma 2 rests, is broken).
struct PlannerFailure {
  std::uint32_t robot = 0;
  SimTime time;
  Vec2 goal, position;
};

// Hooks for recording a run.
class CoverageObserver {
 public:
  virtual ~CoverageObserver() = default;
  virtual void on_motion(SimTime, const Robot&) {}         // after each loop-2 step
  virtual void on_sample(SimTime, CoverageController&) {}  // every sample_period
  virtual void on_finish(SimTime, CoverageController&) {}  // once, when the run ends
};

// Builds robot i's planner; unset, the planner the configuration names.
using PlannerMaker = std::function<std::unique_ptr<Planner>(std::uint32_t robot)>;

class CoverageController {
 public:
  CoverageController(Kernel& kernel, const Environment& env, const Density& density,
                     const std::vector<Vec2>& starts, CoverageConfig config,
                     const PlannerMaker& make_planner = {});

  void set_observer(CoverageObserver* o) { observer_ = o; }
  // Schedules loop 1 and loop 2 for every robot, the samples and the checks.
  void start();
  bool converged() const { return converged_; }
  // The run stopped with robots stalled short of targets that no longer change.
  bool stuck() const { return stuck_; }
  const std::optional<PlannerFailure>& planner_failure() const { return failure_; }

  const std::vector<Robot>& robots() const { return robots_; }
  const CellIntegrator& integrator() const { return integrator_; }
  const CoverageConfig& config() const { return config_; }
  double position_tolerance() const { return position_tol_; }
  double virtual_tolerance() const { return virtual_tol_; }
  std::vector<Vec2> positions() const;
  std::vector<Vec2> virtual_generators() const;
  // The partition of the virtual generators as they are now (cached until one moves).
  const VoronoiPartition& virtual_partition();
  // The partition of the real positions (robots at the same place share one cell), cached
  // until a robot moves.
  const VoronoiPartition& real_partition();
  // geodesic_lloyd only: the geodesic partition of the real positions, cached until a
  // robot moves.
  const GeodesicPartition& geodesic_partition();

  bool decentralized() const { return channel_ != nullptr; }
  const NetworkTotals& network_totals() const { return totals_; }
  const PlannerTotals& planner_totals() const { return planner_totals_; }
  NetworkSample network_sample();
  // Robot i's own cell and its summary as the robot computes them: among the virtual
  // generators it knows (all of them, centralized; its table's, decentralized).
  CellSummary own_cell(std::uint32_t i, ConvexPolygon* cell = nullptr);

 private:
  void loop1(std::uint32_t i);
  // The loop-1 target of a baseline controller for robot i.
  Vec2 baseline_target(std::uint32_t i);
  // What robot i knows: the virtual generators (or, for the baselines, the real positions)
  // of itself and of the robots in its table, in robot-id order, and where its own is in
  // that list (so that generators at one point split their cell as the centralized
  // partition splits it).
  struct Known {
    std::vector<Vec2> points;
    std::size_t self = 0;
  };
  Known known_generators(std::uint32_t i, bool positions) const;
  // Robot i is still acquiring its neighbours (Algorithm 1, line 3) and runs no loop 1.
  bool acquiring(std::uint32_t i);
  void set_goal(Robot& r, Vec2 goal);
  void loop2(Kernel& k, std::uint32_t i);
  void check(Kernel& k);
  void broadcast(Kernel& k, std::uint32_t i);
  void take_reading(std::uint32_t i);
  bool ideal_sensor() const;

  Kernel& kernel_;
  const Environment& env_;
  CellIntegrator integrator_;
  CoverageConfig config_;
  double position_tol_, virtual_tol_, step_;
  std::vector<Robot> robots_;
  CoverageObserver* observer_ = nullptr;
  std::unique_ptr<VoronoiPartition> virtual_partition_, real_partition_;
  PlannerSource planners_;
  std::unique_ptr<VisibilityGraph> graph_;  // geodesic_lloyd
  std::unique_ptr<GeodesicLattice> lattice_points_;
  std::unique_ptr<GeodesicPartition> geodesic_partition_;
  EventKind loop1_kind_ = 0, loop2_kind_ = 0, sample_kind_ = 0, check_kind_ = 0;
  EventKind broadcast_kind_ = 0, deliver_kind_ = 0, sense_kind_ = 0;
  std::vector<RandomStream> noise_rng_, dropout_rng_;
  bool converged_ = false;
  bool stuck_ = false;
  std::optional<PlannerFailure> failure_;
  SimTime t0_;
  // Decentralized operation.
  std::unique_ptr<Channel> channel_;
  std::vector<NeighborTable> tables_;
  std::vector<std::uint64_t> next_seq_;
  std::vector<bool> acquired_;
  std::vector<StateMessage> in_flight_;  // messages on their way, by slot
  std::vector<std::uint32_t> free_slots_;
  NetworkTotals totals_;
  PlannerTotals planner_totals_;
  std::vector<Vec2> lattice_;  // points of Ω for the disagreement estimate
  double lattice_weight_ = 0.0;
};

}  // namespace covsim
