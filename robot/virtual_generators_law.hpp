#pragma once
// The paper's law (Breitenmoser et al. 2010, Algorithm 1, lines 3-5): the centroid of the
// Voronoi cell of the robot's virtual generator among the virtual generators it knows, cell
// ∩ Ω with the density. Virtual generators then move toward their targets as if Ω were
// convex; a robot has converged when its virtual generator rests on its target too.
#include "robot/coverage_law.hpp"

namespace covsim {

class VirtualGeneratorsLaw final : public CoverageLaw {
 public:
  explicit VirtualGeneratorsLaw(const CellIntegrator& integrator) : integrator_(integrator) {}
  Generators generators() const override { return Generators::virtual_generators; }
  bool moves_virtual_generators() const override { return true; }
  Vec2 target(const Robot& robot, const Knowledge& k) override;
  bool at_rest(const Robot& robot, const Tolerances& tolerances) const override;

 private:
  const CellIntegrator& integrator_;
};

LawEntry virtual_generators_entry();

}  // namespace covsim
