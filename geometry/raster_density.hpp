#pragma once
// φ given on a raster (geometry/raster.hpp), constant per cell or bilinear between
// nodes. Integrated exactly: each cell (or patch) a piece overlaps is clipped out, constant
// cells by polygon moments, bilinear patches by a 3 × 3 collapsed Gauss–Legendre rule (exact
// for degree 4: bilinear times |x - r|²).
#include "geometry/density.hpp"
#include "geometry/raster.hpp"

namespace covsim {

class RasterDensity final : public Density {
 public:
  explicit RasterDensity(Raster r) : raster_(std::move(r)) {}
  double operator()(Vec2 x) const override { return raster_(x); }
  Moments integrate(const ConvexPolygon& piece, Vec2 r) const override;

 private:
  Raster raster_;
};

DensityEntry raster_density_entry();

}  // namespace covsim
