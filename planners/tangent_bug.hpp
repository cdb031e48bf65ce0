#pragma once
// TangentBug (Kamon, Rivlin and Rimon, 1998) over a range sensor of any range R (0 for a
// contact sensor, finite, or infinite), extended as in Breitenmoser et al. (2010, Sec.
// III-A) with target projection: a goal inside an obstacle is found unreachable after one
// full loop around that obstacle, and the robot then drives along the boundary to the
// recorded closest boundary point.
//
// Behaviours:
// - Motion to goal: straight at the goal while nothing sensed blocks the way within R;
//   otherwise toward the discontinuity point O minimising d(x, O) + d(O, goal), as long as
//   that heuristic distance keeps decreasing (by at least `progress`).
// - Boundary following, when it stops decreasing: along the blocking obstacle's boundary,
//   in the direction of the last point headed for. d_followed is the smallest distance to
//   the goal of any point of that obstacle sensed for this goal; the robot leaves as soon as
//   a visible point (a discontinuity point, a point of another obstacle, or the free point
//   straight toward the goal) is closer than d_followed by at least `progress`. d_followed
//   is kept per obstacle for the whole goal and lowered to the distance of each leave point,
//   so every leave must beat the one before: the robot cannot chatter or cycle.
//   Following starts at the closest point of the sensed piece that blocks the way.
// - Back at the point where following began without having left: the goal is unreachable.
//   The robot takes the shorter way along the boundary to the closest point (the
//   projection), and reports `projected`.
//
// A new goal restarts motion to goal from the current position. What the robot learned by
// circling an obstacle completely stays in memory: an unreachable goal inside an obstacle
// it has circled is projected at once, without another loop. Every goal ends: a path longer
// than `path_budget`, or proposing to stay put for more than 20 steps in a row, reports
// `stalled`. To get onto an obstacle the robot drives toward it until touching it, so a
// sensed point that noise put short of the wall does not hold it up.
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "planners/planner.hpp"

namespace covsim {

struct TangentBugParams {
  double tolerance = 1e-6;   // arrival, and being on the boundary
  double progress = 1e-9;    // the least decrease that counts as progress
  double path_budget = 1e3;  // the longest path for one goal
  // Defaults scaled to an environment: tolerance 1e-6 and progress 1e-9 of its diameter, a
  // path budget of four times its total boundary length plus its diameter.
  static TangentBugParams for_environment(double diameter, double boundary_length);
};

class TangentBug final : public Planner {
 public:
  explicit TangentBug(TangentBugParams params) : p_(params) {}
  std::string_view name() const override { return "tangent_bug"; }
  void set_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;

  enum class Mode { to_goal, to_boundary, follow, to_projection, done };
  Mode mode() const { return mode_; }

 private:
  struct RingMemory {
    std::map<std::uint32_t, std::pair<Vec2, Vec2>> edges;  // by index in the ring
    std::uint32_t size = 0;                                // known once circled
    bool complete() const { return size > 0 && edges.size() == size; }
  };
  struct Free {
    double distance;                       // free travel along the direction, within range
    std::optional<std::uint32_t> blocker;  // the ring that blocks, if any
    std::optional<std::size_t> piece;      // the sensed piece that blocks, if any
  };

  PlanStep motion_to_goal(const SensorReading& r, double max_step);
  PlanStep begin_following(const SensorReading& r, double max_step, const Free& blocked);
  PlanStep follow(const SensorReading& r, double max_step);
  PlanStep to_projection(const SensorReading& r, double max_step);
  PlanStep go_to_projection(const SensorReading& r, double max_step, std::uint32_t ring);
  PlanStep finish(Vec2 at, PlanStatus s);
  PlanStep move(const SensorReading& r, Vec2 next, PlanStatus s = PlanStatus::moving);

  Free free_distance(const SensorReading& r, Vec2 u, double limit) const;
  // The contact edge to walk along in direction dir (+1 along the ring, -1 against it).
  std::optional<ContactEdge> walking_edge(const SensorReading& r, int dir) const;
  void remember(const ContactEdge& e);
  bool goal_inside(std::uint32_t ring) const;
  // The closest point of a circled ring to the goal, and the index of its edge.
  std::pair<Vec2, std::uint32_t> closest_on_ring(std::uint32_t ring) const;
  // Distance along a circled ring from x (on edge i) to q (on edge j) in direction dir.
  double arc(std::uint32_t ring, Vec2 x, std::uint32_t i, Vec2 q, std::uint32_t j, int dir) const;

  TangentBugParams p_;
  Vec2 goal_;
  bool has_goal_ = false;
  Mode mode_ = Mode::done;
  PlanStatus status_ = PlanStatus::reached;
  double path_ = 0.0;
  double h_prev_ = std::numeric_limits<double>::infinity();
  std::optional<Vec2> heading_;  // the last point headed for in motion to goal
  // Boundary following.
  std::uint32_t ring_ = 0;
  int dir_ = 1;
  Vec2 start_;
  bool left_start_ = false;
  std::uint32_t start_edge_ = 0;
  Vec2 boundary_direction_;
  static constexpr int kMaxIdleSteps = 20;
  int idle_steps_ = 0;
  std::map<std::uint32_t, double> followed_min_;  // per ring, for this goal
  // Projection.
  Vec2 projection_;
  std::uint32_t projection_edge_ = 0;
  std::map<std::uint32_t, RingMemory> memory_;
};

}  // namespace covsim
