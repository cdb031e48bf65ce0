#pragma once
// Where a robot's centre may go: Ω itself for point robots, Ω ⊖ r for disks of radius r
// (geometry/polygon_offset.hpp), split into its connected parts, each an Environment of its
// own. A robot plans, senses and moves in the part it starts in; cells and costs stay on Ω.
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/environment.hpp"

namespace covsim {

class ConfigurationSpace {
 public:
  // radius 0: Ω (referenced, not copied). Throws GeometryError if no point of Ω is r from
  // its boundary, or r is negative or not finite. `env` must outlive this.
  ConfigurationSpace(const Environment& env, double radius);
  // Ω ⊖ r given as its parts, found otherwise (an occupancy grid's cells eroded by r, say).
  // Throws GeometryError if there are none.
  ConfigurationSpace(const Environment& env, double radius,
                     std::vector<std::unique_ptr<const Environment>> parts);

  double radius() const { return radius_; }
  const Environment& environment() const { return *env_; }
  std::size_t part_count() const { return parts_.empty() ? 1 : parts_.size(); }
  const Environment& part(std::size_t k) const { return parts_.empty() ? *env_ : *parts_.at(k); }
  // The part whose closure holds p (within its tolerance), if any.
  std::optional<std::size_t> part_of(Vec2 p) const;
  // Ω's boundary nearer to p than the radius (by more than Ω's tolerance): a body there
  // overlaps an obstacle.
  bool overlaps_boundary(Vec2 p) const;

 private:
  const Environment* env_;
  double radius_;
  std::vector<std::unique_ptr<const Environment>> parts_;  // empty for radius 0
};

}  // namespace covsim
