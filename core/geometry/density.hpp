#pragma once
// The density φ: how much each point of Ω matters. Integrated over convex pieces of Ω
// (φ is zero outside Ω, which the callers ensure by integrating only over Ω).
//
// Accuracy: uniform density and constant rasters are integrated exactly (polygon
// moments); bilinear rasters exactly up to rounding (quadrature of sufficient degree per
// patch); Gaussian mixtures by 8x8-point Gauss-Legendre quadrature on triangles no wider
// than the smallest sigma, which keeps the relative error of mass and centroid below 1e-6
// when sigma is at least 1/20 of the environment's diameter (tests/core/test_density.cpp).
#include <variant>
#include <vector>

#include "core/geometry/convex_polygon.hpp"
#include "core/geometry/raster.hpp"

namespace covsim {

struct GaussianComponent {
  Vec2 mean;
  double sigma = 1.0;
  double weight = 1.0;
};

class Density {
 public:
  static Density uniform(double value = 1.0);
  // φ(x) = floor + Σ weight · exp(-|x - mean|² / (2 sigma²)); components are not normalised.
  // Throws std::invalid_argument for non-positive sigma, negative weights or floor, NaN.
  static Density gaussian_mixture(std::vector<GaussianComponent> components, double floor);
  static Density raster(Raster r);

  double operator()(Vec2 x) const;
  // Moments of φ over a convex polygon (counter-clockwise) relative to r.
  Moments integrate(const ConvexPolygon& piece, Vec2 r) const;
  bool is_uniform() const { return std::holds_alternative<Uniform>(model_); }

 private:
  struct Uniform {
    double value;
  };
  struct Mixture {
    std::vector<GaussianComponent> components;
    double floor;
    double max_width;  // triangles are split until no edge is longer
  };
  using Model = std::variant<Uniform, Mixture, Raster>;
  explicit Density(Model m) : model_(std::move(m)) {}
  Moments integrate_mixture(const Mixture& m, const ConvexPolygon& piece, Vec2 r) const;
  Moments integrate_raster(const Raster& m, const ConvexPolygon& piece, Vec2 r) const;
  Model model_;
};

}  // namespace covsim
