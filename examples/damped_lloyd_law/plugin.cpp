// The plugin route: `covsim run SCENARIO --plugin libdamped_lloyd_plugin.so` with
// "controller": {"type": "damped_lloyd", "gain": 0.5} in the scenario.
#include "sim/plugin.hpp"
#include "damped_lloyd.hpp"

namespace {
void register_law(covsim::Registries& r) {
  r.laws.add(example::damped_lloyd_entry());
}
}  // namespace

COVSIM_PLUGIN(register_law)
