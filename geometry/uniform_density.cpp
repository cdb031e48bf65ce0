#include "geometry/uniform_density.hpp"

#include <cmath>
#include <stdexcept>

namespace covsim {

UniformDensity::UniformDensity(double value) : value_(value) {
  if (!std::isfinite(value) || value <= 0.0)
    throw std::invalid_argument("a uniform density must be positive and finite");
}

Moments UniformDensity::integrate(const ConvexPolygon& piece, Vec2 r) const {
  if (piece.size() < 3) return {};
  return polygon_moments(piece, r).scaled(value_);
}

DensityEntry uniform_density_entry() {
  DensityEntry e;
  e.name = "uniform";
  e.description = "the same value everywhere (the paper's choice)";
  e.params = {ParamSpec::number("value", "", "φ on Ω").greater_than(0).defaults_to(1.0)};
  e.make = [](const DensityContext&, const Params& p) {
    return std::make_shared<const UniformDensity>(p.number("value"));
  };
  return e;
}

}  // namespace covsim
