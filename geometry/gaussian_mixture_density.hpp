#pragma once
// φ(x) = floor + Σ weight · exp(-|x - mean|² / (2 sigma²)); components are not normalised.
//
// Moments are exact (geometry/gaussian_moments.hpp: along the piece's edges, whatever sigma is
// against the piece), each bump's skipped when it cannot change them in double precision, so
// a cell costs its edges times the bumps within reach of it, nothing per unit of area.
#include <vector>

#include "geometry/density.hpp"

namespace covsim {

struct GaussianComponent {
  Vec2 mean;
  double sigma = 1.0;
  double weight = 1.0;
};

class GaussianMixtureDensity final : public Density {
 public:
  // Throws std::invalid_argument for non-positive sigma, negative weights or floor, NaN.
  GaussianMixtureDensity(std::vector<GaussianComponent> components, double floor);
  double operator()(Vec2 x) const override;
  Moments integrate(const ConvexPolygon& piece, Vec2 r) const override;

 private:
  std::vector<GaussianComponent> components_;
  double floor_;
};

DensityEntry gaussian_mixture_density_entry();

}  // namespace covsim
