#pragma once
// Targets set from outside the simulation: by a program or a Python script that drives it
// step by step (Simulation::set_target), a learned controller say. A robot without a target
// holds its position. The run never converges by itself (it goes on to max_time or until the
// driver stops stepping), since only the driver knows when it is done.
#include <map>

#include "robot/coverage_law.hpp"

namespace covsim {

class ExternalLaw final : public CoverageLaw {
 public:
  Generators generators() const override { return Generators::positions; }
  bool moves_virtual_generators() const override { return false; }
  Vec2 target(const Robot& robot, const Knowledge&) override;
  bool at_rest(const Robot&, const Tolerances&) const override { return false; }
  void set_target(std::uint32_t robot, Vec2 target) { targets_[robot] = target; }

 private:
  std::map<std::uint32_t, Vec2> targets_;
};

LawEntry external_law_entry();

}  // namespace covsim
