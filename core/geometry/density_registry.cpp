#include "core/geometry/density_registry.hpp"

#include "core/geometry/gaussian_mixture_density.hpp"
#include "core/geometry/raster_density.hpp"
#include "core/geometry/uniform_density.hpp"

namespace covsim {

Registry<DensityEntry>& density_registry() {
  static Registry<DensityEntry> registry(
      "density",
      {uniform_density_entry(), gaussian_mixture_density_entry(), raster_density_entry()});
  return registry;
}

}  // namespace covsim
