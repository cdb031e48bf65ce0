#pragma once
// Where each robot's planner plans: the part of the free space (Ω ⊖ radius) it starts in, or,
// for a map planner beside a localization (BeliefLayer::map_frame), the part of Ω shrunk
// further by the inflation, the estimate's error times robots.inflation (a costmap's
// inflation: the robot, within that of its estimate, keeps clear of the walls its paths
// pass). A start within the inflation of a wall plans in the inflated part nearest it.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/configuration_space.hpp"

namespace covsim {

class PlannerSpace {
 public:
  // `free`: where robot centres may go (it and `env` outlive this); `radius`: the bodies';
  // `inflation`: how much further the map planners' space is shrunk (0: not at all), and the
  // configured number of standard deviations it stands for (for the error it names).
  PlannerSpace(const Environment& env, const ConfigurationSpace& free, double radius,
               double inflation, double inflation_sigmas);
  ~PlannerSpace();

  // The next robot, starting at `start` in part `free_part` of the free space: the part its
  // planner plans in.
  std::size_t add(Vec2 start, std::size_t free_part);
  std::size_t part_count() const;
  const Environment& part(std::size_t k) const;
  // Where robot i's planner plans.
  const Environment& of(std::uint32_t i) const { return part(part_[i]); }

 private:
  const ConfigurationSpace& free_;
  std::unique_ptr<ConfigurationSpace> inflated_;  // unset: no inflation
  std::vector<std::size_t> part_;                 // robot i's part
};

}  // namespace covsim
