#pragma once
// φ = value everywhere: cells integrate exactly by polygon moments.
#include "geometry/density.hpp"

namespace covsim {

class UniformDensity final : public Density {
 public:
  // Throws std::invalid_argument unless value is positive and finite.
  explicit UniformDensity(double value = 1.0);
  double operator()(Vec2) const override { return value_; }
  Moments integrate(const ConvexPolygon& piece, Vec2 r) const override;
  bool is_uniform() const override { return true; }

 private:
  double value_;
};

DensityEntry uniform_density_entry();

}  // namespace covsim
