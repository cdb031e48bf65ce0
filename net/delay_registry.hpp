#pragma once
// The registry of delay models: a scenario's "network": {"delay": {"model": NAME, ...}}.
#include "net/delay_model.hpp"

namespace covsim {

Registry<DelayEntry>& delay_registry();

}  // namespace covsim
