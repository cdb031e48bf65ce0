#pragma once
// TangentBug (Kamon, Rivlin and Rimon, IJRR 1998) over a range sensor of any range R (0 for a
// contact sensor, finite, or infinite), with the target projection of Breitenmoser et al.
// (2010, Sec. III-A): a goal that lies inside an obstacle is found unreachable by going
// once round that obstacle, and the robot then settles at the obstacle's point closest to
// the goal. The planner reads only what the sensors measure (no obstacle ids): which sensed
// points belong to the followed obstacle it infers from the continuity of the visible
// boundary. docs/tangent_bug.md sets the code beside the algorithm, line by line.
//
// - Motion to goal: toward the node of the local tangent graph (the goal, when the way to it
//   is free within R, or a discontinuity point O) with the least heuristic distance
//   d(x, O) + d(O, goal), for as long as that distance does not increase. When it would
//   increase, the robot is at a local minimum and follows the blocking obstacle: the
//   sensed boundary in the way to the goal.
// - Boundary following, R > 0: along the visible stretch of the followed boundary in the
//   chosen direction, toward its farthest point the robot can head for straight with the
//   stretch before it on the obstacle's side, without touching it. The followed stretch is
//   the one through the point last headed for. R = 0: along the wall by touch. The direction
//   is kept for the whole episode: no way back over the robot's last step, or back beside
//   the way it followed the boundary, is taken while another is open (a robot standing on a
//   corner where the stretch wraps round it would otherwise head for its far end, back
//   along the wall it came by). Motion to goal takes no node back along its last step
//   either, and a straight way stops at a sensed vertex it passes through, where the view
//   changes. d_followed is the least distance to the goal of the followed boundary as
//   sensed since this episode began; d_reach that of the visible free region beyond it. The
//   robot leaves toward the d_reach point as soon as d_reach < d_followed, then resumes
//   motion to goal.
//   Every node it heads for afterwards, until the next leave, must be closer to the goal
//   than that d_followed, so episodes start ever closer to the goal and end.
// - The followed boundary is recorded as the robot goes (R > 0: the sensed stretches, from
//   where the episode began on; R = 0: the robot's own positions). When the record comes
//   back to where it began, in the same direction, the robot has gone round: the record is
//   the obstacle, closed into a polygon. If it encloses the goal (inside a hole, or outside
//   the outer boundary), the goal is unreachable: the robot goes the shorter way to the
//   recorded point closest to the goal, slides along the wall it touches there to the
//   wall's point closest to the goal, and reports `projected` once a touched wall faces the
//   goal. A loop round an obstacle that does not enclose the goal cannot happen in exact
//   arithmetic; should rounding or noise hide the leave, the robot goes to that point and
//   resumes motion to goal from it (counted in `recoveries`), so a reachable goal is never
//   declared unreachable.
//
// Decisions are taken only on a range reading taken where the robot stands: on a stale one
// (the sensor reads less often than the robot steps, or a reading was lost) the robot keeps
// on toward the point its last decision chose. With range noise σ every sensed distance
// carries a margin of 3σ, and an unreachable goal is projected within 6σ.
//
// A goal that moves while the robot is on its way (move_goal) keeps the mode and the episode:
// a robot following a wall follows on, one heading for a node heads on. Every distance to
// the goal changes by at most the move, so h, d_followed and the bound widen by it: what was
// good enough stays so. A leave under way stays committed to its point. A goal moved while
// the robot goes to a projection, or after it ended, starts afresh.
//
// What was learned by going round an obstacle stays across goals: a later goal it encloses
// is projected as soon as the robot touches that obstacle or sees its point closest to the
// goal. A new goal restarts motion to goal from where the robot stands. Every goal ends: a
// path longer than `path_budget`, or 20 steps in a row without moving, reports `stalled`
// (never expected for TangentBug: the planner contract suite checks it does not happen).
#include <limits>
#include <optional>
#include <vector>

#include "planners/local_tangent_graph.hpp"
#include "planners/planner.hpp"
#include "planners/planner_entry.hpp"
#include "planners/recorded_obstacle.hpp"

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
  // The standard deviation (each axis) of how much the position the robot plans from (an
  // odometry) drifts over one step: a point recorded in that frame drifts from where the
  // walls are seen now as the square root of the way walked since.
  double drift = 0.0;
  // Defaults scaled to an environment: tolerance and progress 1e-9 of its diameter, a
  // path budget of ten times its total boundary length plus its diameter.
  static TangentBugParams for_environment(double diameter, double boundary_length);
};

class TangentBug final : public Planner {
 public:
  explicit TangentBug(TangentBugParams params) : p_(params) {}
  std::string_view name() const override { return "tangent_bug"; }
  void set_goal(Vec2 goal) override;
  void move_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;

  enum class Mode { motion_to_goal, follow, leave, to_projection, to_closest, settle, done };
  Mode mode() const { return mode_; }
  // For the current goal, each boundary-following episode: where the robot stood when it
  // began, and the followed boundary point it began from.
  struct Episode {
    Vec2 start, boundary;
  };
  const std::vector<Episode>& episodes() const { return episodes_; }
  std::uint32_t loops() const { return loops_; }
  std::uint32_t recoveries() const { return recoveries_; }
  // For the current goal: the boundary points it headed for in motion to goal (for the
  // obstacles it steered round), each change of node once.
  const std::vector<Vec2>& engaged() const { return engaged_; }
  // For the current goal: the summed length of the straight leave segments it set out on
  // (from the leave point to the reach point), as planned.
  double leave_length() const { return leave_length_; }
  // What it has learned: every obstacle it went round.
  const std::vector<RecordedObstacle>& known() const { return known_; }

 private:
  using Decision = std::optional<PlanStep>;  // nullopt: the mode changed, decide again
  Decision motion_to_goal(const SensorReading& r, double max_step);
  Decision begin_following(const SensorReading& r, Vec2 blocked_at);
  Decision follow(const SensorReading& r, double max_step);
  Decision follow_by_touch(const SensorReading& r, double max_step);
  Decision leave(const SensorReading& r, double max_step);
  Decision loop_closed(const SensorReading& r, RecordedObstacle obstacle);
  // Toward known_[known]'s point closest to the goal, the shorter way round.
  Decision walk_to(const SensorReading& r, std::size_t known, Mode mode);
  Decision walk_on(const SensorReading& r, double max_step);
  // Under drift: the target moved onto the boundary in view, to its point nearest the goal
  // within what the frame may have drifted of the recorded one (the record lies off the walls
  // seen now by as much).
  void reanchor(const SensorReading& r);
  Decision settle(const SensorReading& r, double max_step);
  Decision forget_record();
  // The visible stretch of the followed boundary (the one through head_), its points in the
  // walking direction.
  std::optional<SensedChain> followed_chain(const SensorReading& r) const;
  // Where boundary following heads on a stretch of boundary (its points in the walking
  // order dir): from its place nearest `from` on (or the robot's own, if it stands within
  // `by` of the stretch farther on), the farthest point the robot reaches
  // straight with the stretch before it kept on the obstacle's side (it turns less than half
  // a turn as seen from the robot) and, when `keep_on`, without walking back over its last
  // step; with the stretch's point before it, and its first point beyond where the robot
  // stands (the way along it). None beyond where the robot stands: nullopt.
  struct Ahead {
    Vec2 point, before, next;
  };
  std::optional<Ahead> ahead(const std::vector<Vec2>& stretch, Vec2 from, Vec2 x, int dir,
                             bool keep_on, double by) const;
  // Along the followed stretch in the walking direction, toward its point ahead (past it by
  // the noise margin, along the ray, which range noise does not turn).
  PlanStep chase(const SensorReading& r, const SensedChain& c, double max_step, bool keep_on);
  // Records the followed stretch from the record's end on; true when the record came back to
  // where the episode began.
  bool record(const SensedChain& c);
  // Whether the straight way from x to p runs back along the robot's last step for this goal.
  bool retraces(Vec2 x, Vec2 p) const;
  // Whether the straight way from x to p runs back beside the robot's way in this
  // boundary-following episode for a step or more: within two steps of a part of it walked
  // the other way, and nearer that than any part walked this way (a chord back under a wall
  // it followed).
  bool against_trail(Vec2 x, Vec2 p) const;
  // Toward p, stopping at a vertex of the sensed boundary the straight way passes through.
  PlanStep toward(const SensorReading& r, Vec2 p, double max_step);
  // The next point along the touched wall in dir_, stopping at the edge's end, at the edge's
  // point closest to the goal, and at `stop` if it lies ahead on this edge.
  PlanStep walk(const SensorReading& r, double max_step, std::optional<Vec2> stop);
  PlanStep move_toward(Vec2 x, Vec2 p, double max_step);
  PlanStep finish(Vec2 at, PlanStatus s);
  void resume_motion_to_goal();
  bool by_touch(const SensorReading& r) const { return !(r.range > 0.0); }
  double loop_tolerance() const { return p_.tolerance + 2.0 * p_.noise_margin; }
  // How far the frame the robot plans in may have drifted from the record's beginning:
  // kDriftDeviations standard deviations of the drift over the way walked since.
  static constexpr double kDriftDeviations = 3.5;
  double record_drift() const;

  TangentBugParams p_;
  Vec2 goal_;
  Mode mode_ = Mode::done;
  PlanStatus status_ = PlanStatus::reached;
  // Motion to goal.
  double h_prev_ = std::numeric_limits<double>::infinity();  // heuristic distance last step
  double bound_ = std::numeric_limits<double>::infinity();   // d_followed at the last leave
  std::optional<Vec2> heading_;                              // the node last headed for
  // Boundary following.
  int dir_ = 1;
  Vec2 start_;  // where the robot stood when the episode began
  double walked_ = 0.0;
  bool left_start_ = false;        // the robot has been away from start_ (R = 0)
  bool goal_behind_wall_ = false;  // a leave for the goal in sight met a wall (noise)
  double d_followed_ = 0.0;
  Vec2 leave_to_;
  Vec2 head_;                // the followed boundary's node last headed for
  Vec2 anchor_;              // the followed stretch's point before head_
  std::vector<Vec2> trace_;  // the followed boundary recorded in this episode
  // The robot's way in this episode, its last kTrail positions.
  static constexpr std::size_t kTrail = 256;
  std::vector<Vec2> trail_;
  Vec2 trace_direction_;      // the boundary's direction where the record began
  double traced_ = 0.0;       // the record's length
  double trace_path_ = 0.0;   // the path walked when the record began
  std::size_t obstacle_ = 0;  // in known_: to_projection, to_closest and settle
  RingPlace target_;
  bool straight_ = false;  // the last step went straight for target_
  bool seeking_ = false;   // settle: walking by touch toward target_ from a local minimum
  bool sought_ = false;    // settle: that walk was made
  double seek_arc_ = 0.0;  // its length along the record
  std::vector<RecordedObstacle> known_;
  // Bookkeeping for the goal.
  double path_ = 0.0;
  std::optional<Vec2> last_position_;
  std::optional<Vec2> aim_;  // where the last decision moved toward
  // The direction of the last step that moved; kept across goals, it is the robot's own.
  std::optional<Vec2> motion_;
  bool moved_ = false;  // the robot has moved since the goal was set or moved
  double step_ = 0.0;   // the step length of the current step
  static constexpr int kMaxIdleSteps = 20;
  int idle_steps_ = 0;
  std::vector<Episode> episodes_;
  std::vector<Vec2> engaged_;
  std::uint32_t loops_ = 0, recoveries_ = 0;
  double leave_length_ = 0.0;
};

std::string_view to_string(TangentBug::Mode m);

PlannerEntry tangent_bug_entry();

}  // namespace covsim
