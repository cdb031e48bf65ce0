#pragma once
// Every robot's virtual generator and position as they are now, in robot-id order, each kind
// with a version that changes whenever one of its points moves, and the Voronoi partition of
// each kind computed once per version. What the ideal network gives every robot, and what the
// metrics read.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/voronoi_partition.hpp"
#include "robot/coverage_law.hpp"

namespace covsim {

class GeneratorState {
 public:
  GeneratorState(const CellIntegrator& integrator, const std::vector<Vec2>& starts);
  const std::vector<Vec2>& points(Generators k) const { return kind(k).points; }
  std::uint64_t version(Generators k) const { return kind(k).version; }
  // Moves robot i's point of that kind (a new version only if it changed).
  void move(Generators k, std::uint32_t i, Vec2 p);
  // The partition (coincident points split) of a kind's points as they are now.
  const VoronoiPartition& partition(Generators k) const;

 private:
  struct Kind {
    std::vector<Vec2> points;
    std::uint64_t version = 0;
    mutable std::optional<VoronoiPartition> partition;
    mutable std::uint64_t partition_version = 0;
  };
  const Kind& kind(Generators k) const { return kinds_[static_cast<std::size_t>(k)]; }
  const CellIntegrator& integrator_;
  std::array<Kind, 2> kinds_;
};

}  // namespace covsim
