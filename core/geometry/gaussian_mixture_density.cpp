#include "core/geometry/gaussian_mixture_density.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/geometry/placement.hpp"
#include "core/geometry/quadrature.hpp"
#include "core/random_stream.hpp"

namespace covsim {

namespace {
constexpr int kMixturePoints = 8;  // exact to degree 14 on each triangle

// Calls f on triangles covering the triangle (a, b, c), halving its longest edge until no
// edge is longer than max_width.
template <class F>
void subdivide(Vec2 a, Vec2 b, Vec2 c, double max_width, const F& f, int depth = 0) {
  const double ab = norm2(b - a), bc = norm2(c - b), ca = norm2(a - c);
  const double longest = std::max({ab, bc, ca});
  if (longest <= max_width * max_width || depth > 40) {
    f(a, b, c);
    return;
  }
  if (longest == ab) {
    const Vec2 m = 0.5 * (a + b);
    subdivide(a, m, c, max_width, f, depth + 1);
    subdivide(m, b, c, max_width, f, depth + 1);
  } else if (longest == bc) {
    const Vec2 m = 0.5 * (b + c);
    subdivide(a, b, m, max_width, f, depth + 1);
    subdivide(a, m, c, max_width, f, depth + 1);
  } else {
    const Vec2 m = 0.5 * (c + a);
    subdivide(a, b, m, max_width, f, depth + 1);
    subdivide(m, b, c, max_width, f, depth + 1);
  }
}
}  // namespace

GaussianMixtureDensity::GaussianMixtureDensity(std::vector<GaussianComponent> components,
                                               double floor)
    : components_(std::move(components)), floor_(floor), max_width_(INFINITY) {
  if (!std::isfinite(floor) || floor < 0.0)
    throw std::invalid_argument("floor must be finite and non-negative");
  for (std::size_t i = 0; i < components_.size(); ++i) {
    const auto& c = components_[i];
    if (!is_finite(c.mean) || !std::isfinite(c.sigma) || !std::isfinite(c.weight)) {
      throw std::invalid_argument("component " + std::to_string(i) + " has a non-finite value");
    }
    if (c.sigma <= 0.0)
      throw std::invalid_argument("component " + std::to_string(i) + ": sigma must be positive");
    if (c.weight < 0.0)
      throw std::invalid_argument("component " + std::to_string(i) +
                                  ": weight must be non-negative");
    max_width_ = std::min(max_width_, c.sigma);
  }
}

double GaussianMixtureDensity::operator()(Vec2 x) const {
  double v = floor_;
  for (const auto& c : components_)
    v += c.weight * std::exp(-norm2(x - c.mean) / (2.0 * c.sigma * c.sigma));
  return v;
}

Moments GaussianMixtureDensity::integrate(const ConvexPolygon& piece, Vec2 r) const {
  Moments out;
  if (piece.size() < 3) return out;
  const auto f = [&](Vec2 x) { return (*this)(x); };
  for (std::size_t k = 1; k + 1 < piece.size(); ++k) {
    subdivide(piece[0], piece[k], piece[k + 1], max_width_, [&](Vec2 a, Vec2 b, Vec2 c) {
      out += triangle_moments(a, b, c, r, f, kMixturePoints);
    });
  }
  return out;
}

DensityEntry gaussian_mixture_density_entry() {
  DensityEntry e;
  e.name = "gaussian_mixture";
  e.description = "floor + a sum of Gaussian bumps (not normalised)";
  e.params = {
      ParamSpec::objects("components",
                         {ParamSpec::point("mean", "m",
                                           "centre of the bump; null: drawn uniformly in Ω from "
                                           "the scenario's seed")
                              .or_null(),
                          ParamSpec::number("sigma", "m", "standard deviation").greater_than(0),
                          ParamSpec::number("weight", "", "height of the bump").at_least(0)},
                         "the bumps"),
      ParamSpec::number("floor", "", "value added everywhere").at_least(0).defaults_to(0.0)};
  e.make = [](const DensityContext& ctx, const Params& p) {
    std::vector<GaussianComponent> cs;
    const ParamObjects& components = p.objects("components");
    for (std::size_t k = 0; k < components.size(); ++k) {
      const Params& c = components[k];
      Vec2 mean;
      if (c.has("mean")) {
        mean = c.point("mean");
      } else {
        if (!ctx.seed)
          throw ParamError("components",
                           "a null mean is drawn from the scenario's \"seed\", "
                           "and the scenario has none");
        RandomStream rng(*ctx.seed, k, "density-mean");
        mean = uniform_point(ctx.environment, rng);
      }
      cs.push_back(GaussianComponent{mean, c.number("sigma"), c.number("weight")});
    }
    return std::make_shared<const GaussianMixtureDensity>(std::move(cs), p.number("floor"));
  };
  return e;
}

}  // namespace covsim
