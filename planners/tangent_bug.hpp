#pragma once
// TangentBug (Kamon, Rivlin and Rimon, IJRR 1998) over a range sensor of any range R (0 for a
// contact sensor, finite, or infinite), with the target projection of Breitenmoser et al.
// (2010, Sec. III-A): a goal that lies inside an obstacle is found unreachable by walking
// once round that obstacle, and the robot then settles at the obstacle's point closest to
// the goal. docs/tangent_bug.md sets the code beside the algorithm, line by line.
//
// - Motion to goal: toward the node of the local tangent graph (the goal, when the way to it
//   is free within R, or a discontinuity point O) with the least heuristic distance
//   d(x, O) + d(O, goal), for as long as that distance does not increase. When it would
//   increase, the robot is at a local minimum: it drives toward the goal until it touches
//   the obstacle in the way and follows that obstacle's boundary.
// - Boundary following: along the blocking obstacle, in the direction that continues the
//   motion. d_followed is the least distance to the goal of the followed obstacle's sensed
//   boundary since this episode began (starting with where it began); d_reach that of the
//   visible free region. The robot leaves toward the d_reach point as soon as
//   d_reach < d_followed, then resumes motion to goal. Every node it heads for afterwards,
//   until the next leave, must be closer to the goal than that d_followed: the distance at
//   which boundary following starts falls strictly from one episode to the next, so the
//   robot never returns to an obstacle it left and the episodes end (this is what keeps it
//   from leaving an obstacle only to head for that obstacle's corner again).
// - Back at the point where this episode began, without having left: a loop. The ring is
//   now known exactly; it encloses the goal (the goal lies inside that obstacle, or outside
//   the outer boundary), so the goal is unreachable: the robot walks the shorter way to the
//   ring's point closest to the goal (the projection) and reports `projected`. A loop round a
//   ring that does not enclose the goal cannot happen in exact arithmetic (at the ring's
//   point closest to the goal the way toward it is free, so the robot leaves there); should
//   rounding or range noise hide that leave, the robot walks to that point and resumes
//   motion to goal from it (counted in `recoveries`), so a reachable goal is never declared
//   unreachable.
//
// A goal that moves while the robot is on its way (move_goal) keeps the mode and the episode:
// a robot following a wall follows on, one heading for a node heads on. Every distance to
// the goal changes by at most the move, so h, d_followed and the bound widen by it: what was
// good enough stays so. Without this, a target moved every period restarts motion to goal
// each time, and a robot just past a corner heads back to it (the straight-line heuristic
// of the corner behind beats the one ahead) and shuttles there for as long as the target
// moves. A leave under way stays committed to its point; an approach heads for the goal as
// it is now. A goal moved while the robot walks to a projection, or after it ended, starts
// afresh.
//
// What was learned by walking round an obstacle stays across goals: a later goal inside it
// is projected as soon as the robot touches it. A new goal restarts motion to goal from
// where the robot stands. Every goal ends: a path longer than `path_budget`, or 20 steps in
// a row without moving, reports `stalled` (never expected for TangentBug: the planner
// contract suite checks it does not happen).
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "planners/obstacle_memory.hpp"
#include "planners/planner.hpp"
#include "planners/planner_entry.hpp"

namespace covsim {

struct TangentBugParams {
  // Arrival, and touching the boundary: must be the environment's contact tolerance, so that
  // a wall the planner counts as touched is one the contact sensor reports.
  double tolerance = 1e-9;
  double progress = 1e-9;    // the least decrease that counts as progress
  double path_budget = 1e3;  // the longest path for one goal
  // Added to every sensed distance of the followed obstacle: range noise makes the nearest
  // of many noisy points look closer than the obstacle is.
  double noise_margin = 0.0;
  // Defaults scaled to an environment: tolerance and progress 1e-9 of its diameter, a
  // path budget of ten times its total boundary length plus its diameter.
  static TangentBugParams for_environment(double diameter, double boundary_length);
};

class TangentBug final : public Planner {
 public:
  explicit TangentBug(TangentBugParams params) : p_(params), memory_(params.tolerance) {}
  std::string_view name() const override { return "tangent_bug"; }
  void set_goal(Vec2 goal) override;
  void move_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;

  enum class Mode { motion_to_goal, approach, follow, leave, to_projection, to_closest, done };
  Mode mode() const { return mode_; }
  // For the current goal: the ring followed in each boundary-following episode, the loops
  // closed, and the loops closed round a ring that did not enclose the goal.
  const std::vector<std::uint32_t>& episodes() const { return episodes_; }
  std::uint32_t loops() const { return loops_; }
  // For the current goal: the obstacles it steered round (headed for a point of) in motion
  // to goal or followed, each once, in increasing order.
  const std::vector<std::uint32_t>& engaged() const { return engaged_; }
  std::uint32_t recoveries() const { return recoveries_; }
  // For the current goal: the summed length of the straight leave segments it set out on
  // (from the leave point to the reach point T), as planned.
  double leave_length() const { return leave_length_; }

 private:
  using Decision = std::optional<PlanStep>;  // nullopt: the mode changed, decide again
  Decision motion_to_goal(const SensorReading& r, double max_step);
  Decision approach(const SensorReading& r, double max_step);
  Decision begin_following(const SensorReading& r, std::uint32_t ring);
  Decision follow(const SensorReading& r, double max_step);
  Decision leave(const SensorReading& r, double max_step);
  Decision loop_closed(const SensorReading& r);
  Decision walk_to(const SensorReading& r, std::uint32_t ring, Mode mode);
  Decision walk_on(const SensorReading& r, double max_step);
  // The next point along the followed ring in dir_, stopping at the edge's end, at the
  // edge's point closest to the goal, and at `stop` if it lies ahead on this edge.
  PlanStep walk(const SensorReading& r, double max_step, std::optional<Vec2> stop);
  PlanStep move_toward(Vec2 x, Vec2 p, double max_step);
  PlanStep finish(Vec2 at, PlanStatus s);
  void resume_motion_to_goal();

  TangentBugParams p_;
  ObstacleMemory memory_;
  Vec2 goal_;
  Mode mode_ = Mode::done;
  PlanStatus status_ = PlanStatus::reached;
  // Motion to goal.
  double h_prev_ = std::numeric_limits<double>::infinity();  // heuristic distance last step
  double bound_ = std::numeric_limits<double>::infinity();   // d_followed at the last leave
  std::optional<Vec2> heading_;                              // the node last headed for
  // Boundary following.
  std::uint32_t ring_ = 0;
  int dir_ = 1;
  Vec2 start_;
  double walked_ = 0.0;
  double d_followed_ = 0.0;
  Vec2 leave_to_;
  RingPoint target_;  // to_projection and to_closest
  // Bookkeeping for the goal.
  double path_ = 0.0;
  std::optional<Vec2> last_position_;
  // The direction of the last step that moved; kept across goals, it is the robot's own.
  std::optional<Vec2> motion_;
  static constexpr int kMaxIdleSteps = 20;
  int idle_steps_ = 0;
  std::vector<std::uint32_t> episodes_;
  std::vector<std::uint32_t> engaged_;
  void engage(std::uint32_t ring);
  std::uint32_t loops_ = 0, recoveries_ = 0;
  double leave_length_ = 0.0;
};

std::string_view to_string(TangentBug::Mode m);

PlannerEntry tangent_bug_entry();

}  // namespace covsim
