#pragma once
// The ideal network: every robot knows every generator as it is now, at once, and no
// message is simulated (the centralized controller). Robots share one partition.
#include "robot/generator_state.hpp"
#include "robot/neighbor_view.hpp"

namespace covsim {

class IdealView final : public NeighborView {
 public:
  explicit IdealView(const GeneratorState& state) : state_(state) {}
  bool decentralized() const override { return false; }
  void start(SimTime) override {}
  bool ready(std::uint32_t) override { return true; }
  void refresh(std::uint32_t) override {}
  Knowledge knowledge(std::uint32_t i, Generators kind) const override {
    return Knowledge{state_.points(kind), i, kind, &state_, state_.version(kind)};
  }

 private:
  const GeneratorState& state_;
};

}  // namespace covsim
