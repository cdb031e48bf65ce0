#pragma once
// The planner contract suite: one harness run over every planner, in the spirit of OMPL's
// planner tests. Each case is a random obstacle course (scenarios/obstacle_course) with a
// random start and goal, drawn from (seed, case index) alone; the visibility graph decides
// reachability and the shortest length L*. A planner is driven as a robot would drive it
// (sense, step, move; the world stops a motion at a wall) and checked:
//
// - every proposed step is at most the step length, and (without range noise) stays in Ω;
// - it ends within a step limit;
// - `reached` only at the goal, `projected` only at a closest point of Ω to a goal outside
//   Ω (the projection; with range noise σ, a boundary point no more than 6σ farther from the
//   goal), never for a goal in Ω;
// - for a planner that claims completeness: a goal in Ω is reached, a goal outside Ω ends at
//   its projection, and the path length stays within the planner's bound (below);
// - for the others (potential_field, straight_line): a goal not reached is reported as a
//   stall, honestly.
//
// What a planner promises is declared in its registry entry (PlannerEntry::contract): whether
// it is complete, its path-length bound (L* the shortest path to where it should end), and
// parameters for the suite's courses. tangent_bug: L* + the perimeter of the obstacle followed
// in each boundary-following episode and the way from where it began to that obstacle +
// that of each obstacle only steered round + every leave segment (+ half the enclosing
// obstacle's for a goal outside Ω), ×1.5 with range noise; grid_astar: 1.0824 L* +
// 4 h (v + 1); visibility_graph: L*.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/vec2.hpp"
#include "planners/planner.hpp"
#include "planners/planner_entry.hpp"

namespace covsim {

// Which random cases: obstacle courses (every shape, random starts and goals, reachable or
// not), or combs (scenarios/obstacle_course's comb_course: deep dead-end gaps between the
// robot and its goal, which is always reachable).
enum class CaseFamily { courses, combs };
std::string_view to_string(CaseFamily f);

struct ContractSetup {
  std::string planner = "tangent_bug";
  CaseFamily family = CaseFamily::courses;
  double range = INFINITY;   // the range sensor's range, metres
  double noise_sigma = 0.0;  // Gaussian range noise, metres
  double step = 0.05;        // metres per step
  // The robot's radius: the planner works in the largest part of the course shrunk by it
  // (geometry/configuration_space), drawn with passages wider by 2 × radius, so that the
  // shrunk course keeps the passages a point robot's has; starts lie in that part, and goals
  // outside it (near a wall, in a grown obstacle, beyond a closed passage) are unreachable.
  // The courses family only.
  double radius = 0.0;
  // Whether the planner promises to reach what is reachable (and project the rest); unset:
  // what its registry entry declares (true for a planner given by `make` alone).
  std::optional<bool> complete;
  // grid_astar's cell side (unset: what its entry asks for the courses: a quarter of their
  // narrowest passage, so that every passage holds connected free cells).
  std::optional<double> resolution;
  // What a map planner plans on (planner.map): "given" or "sensed" (planners that offer no
  // such choice plan as they always do).
  std::string map = "given";
  // Builds the planner under test for a course (a user's own planner, say); unset: the
  // planner named `planner`, from the registry.
  std::function<std::unique_ptr<Planner>(const Environment&, const SensorSpec&)> make;
  // A one-line description, e.g. "tangent_bug range=0.5 noise=0" (" combs" for that family,
  // " radius=r" with a radius, " map=sensed" on a sensed map).
  std::string label() const;
};

struct ContractResult {
  std::uint64_t seed = 0, index = 0;
  Vec2 start, goal;
  bool reachable = false;
  PlanStatus status = PlanStatus::moving;
  Vec2 end;
  double length = 0.0;
  double shortest = 0.0;  // L* to the goal (reachable) or to the projection
  double bound = 0.0;     // the path-length bound (infinite when none applies)
  std::size_t steps = 0;
  std::size_t episodes = 0, recoveries = 0;  // tangent_bug's boundary following
  // Where the path walked back over the ground it had just covered (analysis/contract/
  // reversals), and how many of those came before TangentBug had gone round an obstacle.
  std::size_t reversals = 0, early_reversals = 0;
  std::string failure;  // empty when every check passed
  // "covsim planner-contract --planner ... --seed S --case I": reruns this case alone.
  std::string reproducer;
  // Recorded by run_contract_case only: the map, and the robot's path with, per step, what
  // the planner was doing (tangent_bug's mode; empty for other planners).
  std::vector<std::vector<Vec2>> rings;
  std::vector<Vec2> path;
  std::vector<std::string> modes;
};

// Runs case `index` of `seed` for a setup.
ContractResult run_contract_case(const ContractSetup& setup, std::uint64_t seed,
                                 std::uint64_t index);

struct ContractSummary {
  std::size_t cases = 0, reachable = 0, reached = 0, projected = 0, stalled = 0, failures = 0;
  std::size_t recoveries = 0;
  // Cases whose path walked back over its ground; of those, before going round an obstacle.
  std::size_t reversing = 0, early_reversing = 0;
  double worst_ratio = 0.0;            // path length / L*, over the reached goals
  std::uint64_t worst_ratio_case = 0;  // the case index of worst_ratio, to rerun it
  double mean_ratio = 0.0;
  std::size_t ratio_cases = 0;         // the reached goals with L* > 0 that the ratios cover
  double worst_bound_use = 0.0;        // path length / bound, over the cases with a bound
  std::vector<ContractResult> failed;  // the first few failures, with reproducers
};

// Cases first, first + 1, ..., first + count - 1 of `seed`, on `jobs` threads (results do
// not depend on the thread count). `progress` is called after each case, if given.
ContractSummary run_contract(const ContractSetup& setup, std::uint64_t seed, std::uint64_t first,
                             std::uint64_t count, unsigned jobs = 1,
                             const std::function<void(const ContractResult&)>& progress = {});

// Why the suite does not check a registered planner, if it does not: a planner that does not
// avoid obstacles (Planner::avoids_obstacles(): `none`) drives through walls, and the
// contract is about keeping the robot in Ω. Throws std::invalid_argument for an unknown name.
std::optional<std::string> contract_refusal(std::string_view planner);

// The suite over every entry of planner_registry() as it stands (a plugin's or a program's
// planners included, if registered first), each on the same cases of `setup` (its planner
// name aside) and checked for what its entry declares.
struct RegistryContract {
  std::vector<std::pair<std::string, ContractSummary>> checked;  // in registry order
  std::vector<std::pair<std::string, std::string>> refused;      // name, reason
};
RegistryContract run_registry_contract(const ContractSetup& setup, std::uint64_t seed,
                                       std::uint64_t first, std::uint64_t count, unsigned jobs = 1);

// The range effect: the same cases at each sensor range. Per range, over the cases every
// range reached with L* > 0: the mean of path / L*, and the mean and worst of the path over
// the contact sensor's path on the same case (R = 0, which `ranges` must hold).
struct RangePoint {
  double range = 0.0;
  double mean_ratio = 0.0;       // path / L*
  double mean_vs_contact = 0.0;  // path / the contact sensor's path
  double worst_vs_contact = 0.0;
  std::size_t failures = 0;  // cases that broke the contract at this range
};
struct RangeCurve {
  std::vector<RangePoint> points;  // in the order of `ranges`
  std::size_t cases = 0;           // the cases the means cover
};
RangeCurve range_curve(const ContractSetup& setup, const std::vector<double>& ranges,
                       std::uint64_t seed, std::uint64_t first, std::uint64_t count,
                       unsigned jobs = 1);

}  // namespace covsim
