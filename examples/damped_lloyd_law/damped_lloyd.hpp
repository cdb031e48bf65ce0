#pragma once
// A coverage law built outside covsim's source tree: the paper's Lloyd on virtual
// generators, but each loop-1 target goes only a fraction `gain` of the way from the virtual
// generator to its cell's centroid (an under-relaxed Lloyd step). gain = 1 is the paper's.
#include "robot/coverage_law.hpp"

namespace example {

class DampedLloyd final : public covsim::CoverageLaw {
 public:
  DampedLloyd(const covsim::CellIntegrator& integrator, double gain)
      : integrator_(integrator), gain_(gain) {}
  covsim::Generators generators() const override { return covsim::Generators::virtual_generators; }
  bool moves_virtual_generators() const override { return true; }
  covsim::Vec2 target(const covsim::Robot& robot, const covsim::Knowledge& k) override;
  bool at_rest(const covsim::Robot& robot, const covsim::Tolerances& t) const override;

 private:
  const covsim::CellIntegrator& integrator_;
  double gain_;
};

// Its registry entry: name "damped_lloyd", parameter gain in (0, 1], default 0.5.
covsim::LawEntry damped_lloyd_entry();

}  // namespace example
