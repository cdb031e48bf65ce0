#pragma once
// Lloyd under the geodesic distance in Ω (the paper's Section II-B2, after Pimenta et al.):
// target = p + gain (T - p), T the geodesic Lloyd point of the robot's geodesic cell among
// the positions it knows (GeodesicPartition: exact distances on the visibility graph,
// integrals on a lattice of the given spacing). A full step (gain 1) overshoots near
// obstacles' corners, where the directions to the points behind them turn quickly, and can
// oscillate forever.
#include <memory>
#include <optional>

#include "geometry/geodesic_partition.hpp"
#include "robot/coverage_law.hpp"

namespace covsim {

class GeodesicLloydLaw final : public CoverageLaw {
 public:
  GeodesicLloydLaw(const Environment& env, const Density& density, double resolution, double gain);
  Generators generators() const override { return Generators::positions; }
  bool moves_virtual_generators() const override { return false; }
  Vec2 target(const Robot& robot, const Knowledge& k) override;

 private:
  double gain_;
  std::unique_ptr<VisibilityGraph> graph_;
  std::unique_ptr<GeodesicLattice> lattice_;
  // The partition of every robot's position, while the ideal network's positions are those.
  std::optional<GeodesicPartition> shared_;
  std::uint64_t shared_version_ = 0;
};

LawEntry geodesic_lloyd_entry();

}  // namespace covsim
