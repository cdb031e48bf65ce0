#pragma once
// How long a delivered message takes. An extension point: a delay model is this interface
// plus one entry in delay_registry(). Each directed link has its own random stream.
#include <functional>
#include <memory>

#include "core/random_stream.hpp"
#include "core/registry.hpp"

namespace covsim {

class DelayModel {
 public:
  virtual ~DelayModel() = default;
  // Seconds, >= minimum(). Draws only from rng.
  virtual double sample(RandomStream& rng) const = 0;
  // The least delay it can give.
  virtual double minimum() const = 0;
  // Always zero (the ideal channel has such a model).
  virtual bool instantaneous() const { return false; }
};

using DelayEntry = Component<std::function<std::shared_ptr<const DelayModel>(const Params&)>>;

}  // namespace covsim
