#pragma once
// Lloyd on the real positions (the paper's Section II-B, first critical case): each robot
// drives at the centroid of its own Voronoi cell ∩ Ω among the positions it knows. No
// virtual generators (they follow the positions).
#include "robot/coverage_law.hpp"

namespace covsim {

class EuclideanLloydLaw final : public CoverageLaw {
 public:
  explicit EuclideanLloydLaw(const CellIntegrator& integrator) : integrator_(integrator) {}
  Generators generators() const override { return Generators::positions; }
  bool moves_virtual_generators() const override { return false; }
  Vec2 target(const Robot& robot, const Knowledge& k) override;

 private:
  const CellIntegrator& integrator_;
};

LawEntry euclidean_lloyd_entry();

}  // namespace covsim
