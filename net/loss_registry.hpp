#pragma once
// The registry of loss models: a scenario's "network": {"loss": {"model": NAME, ...}}.
#include "net/loss_model.hpp"

namespace covsim {

Registry<LossEntry>& loss_registry();

}  // namespace covsim
