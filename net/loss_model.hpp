#pragma once
// Whether a message is lost on its directed link. An extension point: a loss model is this
// interface plus one entry in loss_registry(). Each directed link has its own random stream
// and a state word for models with memory (Gilbert-Elliott's good/bad state).
#include <cstdint>
#include <functional>
#include <memory>

#include "core/random_stream.hpp"
#include "core/registry.hpp"

namespace covsim {

struct LinkState {
  std::uint64_t state = 0;  // the model's own, per directed link; 0 at the start
};

class LossModel {
 public:
  virtual ~LossModel() = default;
  // One message over a link `distance` metres long: whether it is lost. Draws only from rng.
  virtual bool lost(LinkState& link, RandomStream& rng, double distance) const = 0;
  // A model that never loses a message draws nothing (the ideal channel has it).
  virtual bool lossless() const { return false; }
};

using LossEntry = Component<std::function<std::shared_ptr<const LossModel>(const Params&)>>;

}  // namespace covsim
