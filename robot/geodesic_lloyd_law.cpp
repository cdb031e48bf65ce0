#include "robot/geodesic_lloyd_law.hpp"

#include <cmath>

namespace covsim {

GeodesicLloydLaw::GeodesicLloydLaw(const Environment& env, const Density& density,
                                   double resolution, double gain)
    : gain_(gain),
      graph_(std::make_unique<VisibilityGraph>(env)),
      lattice_(std::make_unique<GeodesicLattice>(*graph_, density, resolution)) {}

Vec2 GeodesicLloydLaw::target(const Robot&, const Knowledge& k) {
  const Vec2 p = k.points[k.self];  // where the robot is, as it knows it
  if (k.version) {
    if (!shared_ || shared_version_ != *k.version) {
      shared_.emplace(*lattice_, k.points);
      shared_version_ = *k.version;
    }
    return p + gain_ * (shared_->cell(k.self).target - p);
  }
  return p + gain_ * (GeodesicPartition(*lattice_, k.points).cell(k.self).target - p);
}

LawEntry geodesic_lloyd_entry() {
  const auto lattice = [](const Environment& env) { return env.diameter() / 100.0; };
  const auto resolution = [lattice](const Environment& env, const Params& p) {
    return p.maybe_number("resolution").value_or(lattice(env));
  };
  LawEntry e;
  e.name = "geodesic_lloyd";
  e.needs_map = true;
  e.description = "Lloyd under the geodesic distance in Ω, a damped step toward its Lloyd point";
  e.params = {ParamSpec::number("resolution", "m", "spacing of the integration lattice")
                  .greater_than(0)
                  .derived("1/100 of the diameter of Ω's bounding box",
                           [lattice](const Environment& env) { return lattice(env); }),
              ParamSpec::number("gain", "", "fraction of the step to the geodesic Lloyd point")
                  .greater_than(0)
                  .at_most(1)
                  .defaults_to(0.25)};
  e.check = [resolution](const Environment& env, const Params& p) {
    const double h = resolution(env, p);
    const Vec2 size = env.bounds().size();
    if (std::ceil(size.x / h) * std::ceil(size.y / h) > double(1 << 22)) {
      throw ParamError("resolution",
                       "resolution too fine for this environment: more than 4194304 cells");
    }
  };
  // In a convex Ω its Lloyd point is the centroid of the cell's lattice points: within a
  // lattice spacing of the cell's own.
  e.contract.convex_step_tolerance = resolution;
  e.make = [resolution](const LawContext& ctx, const Params& p) {
    return std::make_unique<GeodesicLloydLaw>(ctx.environment, ctx.density,
                                              resolution(ctx.environment, p), p.number("gain"));
  };
  return e;
}

}  // namespace covsim
