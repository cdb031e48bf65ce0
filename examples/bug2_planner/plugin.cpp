// The plugin route: `covsim run SCENARIO --plugin libbug2_plugin.so` with
// "planner": {"type": "bug2"} in the scenario.
#include "sim/plugin.hpp"
#include "bug2.hpp"

namespace {
void register_bug2(covsim::Registries& r) {
  r.planners.add(example::bug2_entry());
}
}  // namespace

COVSIM_PLUGIN(register_bug2)
