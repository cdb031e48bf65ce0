#include "geometry/gaussian_mixture_density.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/random_stream.hpp"
#include "geometry/placement.hpp"
#include "geometry/quadrature.hpp"

namespace covsim {

namespace {
constexpr int kMixturePoints = 8;  // exact to degree 14 on each triangle

// Beyond this many standard deviations a bump is below 1e-31 of its height: left to the
// quadrature of the floor.
constexpr double kReach = 12.0;

double distance_to_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  const double d1 = cross(b - a, p - a), d2 = cross(c - b, p - b), d3 = cross(a - c, p - c);
  if ((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0)) return 0.0;
  const auto seg = [&](Vec2 u, Vec2 v) {
    const Vec2 e = v - u;
    const double t = std::clamp(dot(p - u, e) / std::max(norm2(e), 1e-300), 0.0, 1.0);
    return distance(p, u + t * e);
  };
  return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

// Calls f on triangles covering the triangle (a, b, c), halving its longest edge while it is
// longer than the σ of a bump within reach of it: the cost follows the bumps, not the ratio
// of Ω to σ.
template <class F>
void subdivide(Vec2 a, Vec2 b, Vec2 c, const std::vector<GaussianComponent>& bumps, const F& f,
               int depth = 0) {
  const double ab = norm2(b - a), bc = norm2(c - b), ca = norm2(a - c);
  const double longest = std::max({ab, bc, ca});
  double max_width = INFINITY;
  for (const GaussianComponent& g : bumps)
    if (g.sigma < max_width && distance_to_triangle(g.mean, a, b, c) < kReach * g.sigma)
      max_width = g.sigma;
  if (longest <= max_width * max_width || depth > 40) {
    f(a, b, c);
    return;
  }
  if (longest == ab) {
    const Vec2 m = 0.5 * (a + b);
    subdivide(a, m, c, bumps, f, depth + 1);
    subdivide(m, b, c, bumps, f, depth + 1);
  } else if (longest == bc) {
    const Vec2 m = 0.5 * (b + c);
    subdivide(a, b, m, bumps, f, depth + 1);
    subdivide(a, m, c, bumps, f, depth + 1);
  } else {
    const Vec2 m = 0.5 * (c + a);
    subdivide(a, b, m, bumps, f, depth + 1);
    subdivide(m, b, c, bumps, f, depth + 1);
  }
}
}  // namespace

GaussianMixtureDensity::GaussianMixtureDensity(std::vector<GaussianComponent> components,
                                               double floor)
    : components_(std::move(components)), floor_(floor) {
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
    subdivide(piece[0], piece[k], piece[k + 1], components_, [&](Vec2 a, Vec2 b, Vec2 c) {
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
