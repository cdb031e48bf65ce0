#include "geometry/gaussian_mixture_density.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/random_stream.hpp"
#include "geometry/gaussian_moments.hpp"
#include "geometry/placement.hpp"

namespace covsim {

namespace {
// A bump whose whole mass over a piece stays below this fraction of what the piece is already
// known to hold cannot change its moments in double precision: it is left out.
constexpr double kNegligible = 1e-17;

// Squared distance from p to the box (0 inside).
double distance2(Vec2 p, const Box& b) {
  const double dx = std::max({b.lo.x - p.x, 0.0, p.x - b.hi.x});
  const double dy = std::max({b.lo.y - p.y, 0.0, p.y - b.hi.y});
  return dx * dx + dy * dy;
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
  if (piece.size() < 3) return {};
  Box box;
  for (Vec2 v : piece)
    box.add(v);
  const Moments area = polygon_moments(piece, r);
  // Each bump's mass over the piece is at most its weight times the piece's area times its
  // height at the box's nearest point. Bumps are taken from the largest bound down, and the
  // rest left out once all of them together could not reach kNegligible of what was summed:
  // the moments are those of the whole mixture to the last bit.
  struct Bound {
    double mass;
    std::size_t index;
  };
  std::vector<Bound> bounds;
  bounds.reserve(components_.size());
  double rest = 0.0;
  for (std::size_t k = 0; k < components_.size(); ++k) {
    const GaussianComponent& c = components_[k];
    const double b =
        c.weight * area.mass * std::exp(-distance2(c.mean, box) / (2.0 * c.sigma * c.sigma));
    if (b > 0.0) bounds.push_back({b, k});
    rest += b;
  }
  std::sort(bounds.begin(), bounds.end(), [](const Bound& a, const Bound& b) {
    return a.mass > b.mass || (a.mass == b.mass && a.index < b.index);
  });
  Moments out = area.scaled(floor_);
  for (const Bound& b : bounds) {
    if (rest <= kNegligible * out.mass) break;
    const GaussianComponent& c = components_[b.index];
    out += gaussian_moments(piece, c.mean, c.sigma, r).scaled(c.weight);
    rest -= b.mass;
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
