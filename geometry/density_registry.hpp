#pragma once
// The registry of densities: a scenario's "density": {"type": NAME, ...} names one.
#include "geometry/density.hpp"

namespace covsim {

Registry<DensityEntry>& density_registry();

}  // namespace covsim
