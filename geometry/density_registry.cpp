#include "geometry/density_registry.hpp"

#include "geometry/gaussian_mixture_density.hpp"
#include "geometry/raster_density.hpp"
#include "geometry/uniform_density.hpp"

namespace covsim {

Registry<DensityEntry>& density_registry() {
  static Registry<DensityEntry> registry(
      "density",
      {uniform_density_entry(), gaussian_mixture_density_entry(), raster_density_entry()});
  return registry;
}

}  // namespace covsim
