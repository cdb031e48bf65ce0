#pragma once
// What each robot believes (the belief layer): where it is and what Ω is. Where it is: with
// the localization `exact` (the paper's), its position; else its localization's estimate in Ω
// and the odometry its planner works in (localization.hpp). What Ω is: Ω itself when known,
// else the map it has built and shared (mapping.hpp), in which it computes its cell. Loop 1
// and the planning layer ask it; the controller tells it of each motion.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/kernel.hpp"
#include "geometry/environment.hpp"
#include "planners/planner.hpp"
#include "robot/coverage_config.hpp"
#include "robot/coverage_law.hpp"
#include "robot/localization.hpp"
#include "robot/robot.hpp"

namespace covsim {

class Mapping;

class BeliefLayer {
 public:
  // `step`: the motion step's length (m); `tolerance`: the position tolerance; `position`:
  // where robot i really is; `free_space`: robot i's free space.
  BeliefLayer(Kernel& kernel, const Environment& env, const Density& density,
              const std::vector<Vec2>& starts, const CoverageConfig& config, double step,
              double tolerance, std::function<Vec2(std::uint32_t)> position,
              std::function<const Environment&(std::uint32_t)> free_space);
  ~BeliefLayer();

  // Schedules the localization's events and the first readings of the robots' maps.
  void start(SimTime t0, const std::vector<Robot>& robots);

  // Null with exact localization.
  const Localization* localization() const { return localization_.get(); }
  // Null when Ω is known.
  Mapping* mapping() { return mapping_.get(); }
  const Mapping* mapping() const { return mapping_.get(); }
  // What the planners are told of their sensing: its range noise, and how much the position
  // they plan from (the odometry) jumps.
  const SensorSpec& sensing() const { return sensing_; }

  // Where robot r believes it is: its localization's estimate, taken into its free space (it
  // knows it is not inside a wall); its position with exact localization.
  Vec2 known_position(const Robot& r);
  // Where robot r's planner believes it is: its odometry (a planner that senses works in its
  // frame, so the walls it senses never jump), or, for a planner on Ω's map, the estimate;
  // its position with exact localization.
  Vec2 planner_position(const Robot& r);
  // A point of Ω in the frame robot r's planner works in; a point of r's free space stays in
  // it (the map read in that frame). A planner on Ω's map works in Ω's frame.
  Vec2 in_planner_frame(const Robot& r, Vec2 p);
  // Whether the planners plan on Ω's map from the estimate (a map planner beside a
  // localization), and by how much that map is inflated: the configured number of standard
  // deviations of the estimate's error (m).
  bool map_frame() const { return map_frame_; }
  double inflation() const { return inflation_; }
  // For a planner on Ω's map: whether robot r's estimate jumped (a fix) since its last
  // motion by more than it can tell; it then plans again from there.
  bool estimate_jumped(const Robot& r);
  // Where robot r believes its centre may go, standing where it is: its map's free space
  // when it maps Ω, else its free space.
  const Environment& believed_free_space(const Robot& r) const;
  // How near its target a robot counts as there: the position tolerance, or, with a
  // localization, not nearer than three standard deviations of its estimate's jitter (it
  // cannot tell).
  double within_reach() const;
  // How near its planner's goal a robot counts as there by where its planner believes it is
  // (every motion, however short, drifts an odometry).
  double planner_reach() const;
  // The position tolerance, or kReachDeviations standard deviations (on each axis) of a
  // position's jitter if more: a 2D Gaussian jump goes beyond 3.5 of them with probability
  // exp(-3.5² / 2), 0.2%.
  static constexpr double kReachDeviations = 3.5;
  double reach(double sigma) const;
  // Whether robot r's planner's goal lies outside its free space as it senses the walls
  // (its planner may find it unreachable): with a localization, nearer the boundary than the
  // robot can tell, or than its odometry has drifted while it walked, counts too.
  bool goal_unreachable(const Robot& r) const;

  // What robot i knows, for a robot that maps Ω: its cells in its belief (`integrator`), from
  // a partition shared per belief when it knows every generator as it is now.
  void believe(Knowledge& k, const CellIntegrator& integrator);

  // A loop-2 step begins for robot r (the localization's error is measured).
  void tick(const Robot& r);
  // Robot r's body moves to p, `length` away (its map's readings on the way).
  void moving(const Robot& r, Vec2 p, double length, SimTime now);
  // Robot r's body moved by d over a loop-2 step (what its odometry makes of it).
  void moved(const Robot& r, Vec2 d);
  // Robot r arrived at its planner's step with this status, at its position.
  void arrived(const Robot& r, PlanStatus status, SimTime now);

  // The mean and the largest distance between a robot's estimate and its position over every
  // loop-2 step of every robot, and the tracking fixes delivered.
  double localization_error_mean() const {
    return localization_steps_ == 0
               ? 0.0
               : localization_error_sum_ / static_cast<double>(localization_steps_);
  }
  double localization_error_max() const { return localization_error_max_; }
  std::uint64_t fixes() const { return localization_ ? localization_->fixes() : 0; }
  // Times a robot that maps Ω found unreachable a goal its map placed in free space.
  std::uint64_t discoveries() const { return discoveries_; }

 private:
  std::function<const Environment&(std::uint32_t)> free_space_;
  double step_, tolerance_;
  std::unique_ptr<Localization> localization_;  // unset: exact
  std::unique_ptr<Mapping> mapping_;            // unset: Ω known (environment.known full)
  SensorSpec sensing_;
  struct BelievedPartition {
    const CellIntegrator* integrator = nullptr;
    std::uint64_t version = 0;
    std::optional<VoronoiPartition> partition;
  };
  BelievedPartition believed_[2];  // of the virtual generators, of the positions
  double localization_error_sum_ = 0.0, localization_error_max_ = 0.0;
  std::uint64_t localization_steps_ = 0;
  std::uint64_t discoveries_ = 0;
  bool map_frame_ = false;
  double inflation_ = 0.0;
  std::vector<Vec2> after_motion_;  // map frame: each robot's estimate after its last motion
};

}  // namespace covsim
