#pragma once
// φ(x) = floor + Σ weight · exp(-|x - mean|² / (2 sigma²)); components are not normalised.
//
// Accuracy: 8x8-point Gauss-Legendre quadrature on triangles no wider than the smallest
// sigma, which keeps the relative error of mass and centroid below 1e-6 when sigma is at
// least 1/20 of the environment's diameter (tests/geometry/test_density.cpp).
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
