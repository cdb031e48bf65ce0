#pragma once
// What the map planners share on a sensed map (planner.map "sensed"): a robot's planner adds
// its readings to a SensedMap of the walls seen, with unseen space free (its own, or one the
// robots of a centralized run share, PlannerContext::shared_map), plans a whole path on it
// when the goal changes, and plans again from scratch whenever the map gains a wall that the
// rest of its path meets (full replanning on change; D* Lite would repair the last search
// instead, for the same paths).
//
// A goal the map cannot reach is unreachable in Ω too, since the map holds no wall Ω does
// not: the walls that cut it off were seen whole. The robot then goes to the closest point of
// those walls to the goal (the projection, which TangentBug finds the same way under the
// policy `discover`), chosen again when a wall nearer the goal comes into view, and reports
// `projected` there; no way out of where it stands reports `stalled`.
//
// Under range noise the walls held lie up to a few σ off the true ones, on either side: the
// landing may stop short of the wall, or a wall seen too near may hide a goal that lies in Ω.
// So with a noisy map the robot settles by touch, which is exact: from the path's end it drives
// straight for the goal, reaching it if nothing is in the way; against a wall it touches it
// slides to the point of the touched walls closest to the goal and tries again from there,
// and reports `projected` where the goal lies straight into the walls it touches. The
// distance to the goal only falls on the way, so the settling ends. A touch supersedes the
// noisy pieces beside it (SensedMap::add): a robot stopped by a wall on its way learns that
// the goal lies behind it, not within the noise of it, and plans round.
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/environment.hpp"
#include "planners/path_follower.hpp"
#include "planners/planner.hpp"
#include "planners/planner_entry.hpp"
#include "planners/sensed_map.hpp"

namespace covsim {

class SensedMapPlanner : public Planner {
 public:
  void set_goal(Vec2 goal) override;
  PlanStep step(const SensorReading& reading, double max_step) override;
  const SensedMap& map() const { return *map_; }
  // The map the path was planned on: the robot's, or its finer grid (below).
  const SensedMap& planning_map() const { return *planning_; }
  // The path being followed (from where the robot stood when it was planned), and the goal
  // it ends at (the projection once the goal was found unreachable).
  const std::vector<Vec2>& path() const { return follower_.path(); }
  std::size_t replans() const { return replans_; }
  PlannerPicture picture() const override;
  // A neighbour's walls join the map; the next step replans if they block the way.
  void learn(const std::vector<SensedPiece>& walls) override;

 protected:
  // `env` is the robot's free space: the planner takes its tolerance from it, no more.
  SensedMapPlanner(const Environment& env, std::shared_ptr<SensedMap> map)
      : tol_(env.tolerance()), map_(std::move(map)), planning_(map_.get()) {}
  // A path from start to goal on the map, start first, goal last, with the free cells each
  // enters the grid by (SensedMap::entry); nullopt if there is none.
  virtual std::optional<std::vector<Vec2>> plan(Vec2 start, std::uint32_t from, Vec2 goal,
                                                std::uint32_t to) = 0;

 private:
  std::optional<std::vector<Vec2>> route(const SensedMap& m, Vec2 start, Vec2 goal);
  void replan(Vec2 x);
  // On `m`: whether a path to the goal was found (and is followed), else the projection
  // there, if any.
  // `reach`: the cells of `m` the robot's cell reaches, when it enters the grid (else empty).
  bool plan_on(const SensedMap& m, Vec2 x, std::optional<SensedMap::Landing>& landing,
               std::vector<std::uint8_t>& reach);
  // Whether the landing leaves a wall nearer the goal than itself: on an exact map the walls
  // that cut a goal off were seen from the robot's side, so the cells closed a way.
  bool wall_nearer_than(const std::optional<SensedMap::Landing>& landing) const;
  // Whether the map's cells part the robot (`reach`: the cells its cell reaches) from y, a
  // point it stood at: they closed a way it took.
  bool cut_off(const std::vector<std::uint8_t>& reach, Vec2 y) const;
  // The finer grid, brought up to date with the robot's map; nullptr past its size.
  const SensedMap* finer_map();
  // Whether the rest of the path, from x, is still clear on the map, which gained the pieces
  // stretches from `first_new` on (SensedMap::added) since it was last looked at.
  bool ahead_clear(Vec2 x, std::size_t first_new) const;
  // On the way to a projection: whether a wall that came into view since it was chosen lies
  // nearer the goal.
  bool nearer_wall() const;
  // On a noisy map: a path to the nearest free cell, for a robot no leg leaves by the map;
  // whether there is one.
  bool escape(Vec2 x);
  // A step of the settling by touch (above), and the first.
  PlanStep settle(const SensorReading& r, double max_step);
  PlanStep start_settling(const SensorReading& r, double max_step);

  double tol_;
  std::shared_ptr<SensedMap> map_;
  // An exact map's cells may close a way the pieces leave open (a slot of a few cells whose
  // walls were learnt by touch): where the robot's grid finds no way to the goal and a wall
  // lies nearer it than the landing, or they part the robot from where it set out, the
  // planner tries the same pieces on cells kFiner times finer (built when first needed, then
  // kept up to date) before it settles for the landing.
  static constexpr std::int32_t kFiner = 2;
  static constexpr double kMaxFinerCells = double(1 << 22);
  std::unique_ptr<SensedMap> finer_;
  bool finer_tried_ = false;
  std::size_t finer_synced_ = 0;  // the map's added stretches the finer grid holds
  const SensedMap* planning_ = nullptr;
  Vec2 set_from_;                       // where the robot stood when it first planned for this goal
  std::size_t seen_pieces_ = 0;         // the map's added stretches when it last looked
  std::size_t seen_supersessions_ = 0;  // and its supersessions
  // Plans for the goal again after a touch superseded noisy pieces, while projecting.
  static constexpr int kMaxReroutes = 10;
  int reroutes_ = 0;
  Vec2 goal_;
  bool planned_ = false, projecting_ = false;
  PlanStatus status_ = PlanStatus::reached, arrival_ = PlanStatus::reached;
  PathFollower follower_;
  std::size_t replans_ = 0;
  double landing_distance_ = 0.0;   // from the goal to the projection headed for
  std::size_t landing_pieces_ = 0;  // the map's added stretches when it was chosen
  // Settling by touch: whether it is, where the last step was proposed from, and where it
  // slides to along the walls touched (none: straight for the goal).
  bool settling_ = false, escaping_ = false;
  Vec2 tried_from_;
  // Where the last step that should have moved the robot was proposed from, on a noisy map.
  Vec2 proposed_from_{INFINITY, INFINITY};
  // Settling: steps held by no wall it touches.
  int held_untouched_ = 0;
  // Escaping: where from, the cells tried from there, and how often for this goal (past a
  // hundred, the robot settles by touch instead: escapes could go round in a cycle).
  static constexpr int kMaxEscapes = 100;
  int escapes_ = 0;
  Vec2 escape_from_;
  std::vector<std::uint32_t> escape_tried_;
  std::optional<Vec2> slide_;
};

// A sensed map for planners in `env`, the robot's free space: cells of side `resolution`
// over its bounding box, the sensor's spread for merging pieces.
std::shared_ptr<SensedMap> sensed_map_for(const Environment& env, double resolution,
                                          const SensorSpec& sensor);

}  // namespace covsim
