// A plugin whose registering function throws something that is no std::exception: covsim
// must refuse it (exit 2, naming it), not terminate.
#include "sim/plugin.hpp"

namespace {
void register_nothing(covsim::Registries&) {
  throw 42;
}
}  // namespace

COVSIM_PLUGIN(register_nothing)
