#include "damped_lloyd.hpp"

namespace example {

using namespace covsim;

Vec2 DampedLloyd::target(const Robot&, const Knowledge& k) {
  const Vec2 g = k.points[k.self];
  return g + gain_ * (own_cell_summary(integrator_, k).centroid - g);
}

bool DampedLloyd::at_rest(const Robot& r, const Tolerances& t) const {
  // At rest when the virtual generator is on its target and that target no longer moves: the
  // full Lloyd step from it would stay within the tolerance too.
  return distance(r.virtual_target, r.virtual_generator) <= t.virtual_generator * gain_;
}

LawEntry damped_lloyd_entry() {
  LawEntry e;
  e.name = "damped_lloyd";
  e.description = "Lloyd on virtual generators with an under-relaxed step (an example law)";
  e.params = {ParamSpec::number("gain", "", "fraction of the way to the centroid")
                  .greater_than(0)
                  .at_most(1)
                  .defaults_to(0.5)};
  e.make = [](const LawContext& ctx, const Params& p) {
    return std::make_unique<DampedLloyd>(ctx.integrator, p.number("gain"));
  };
  return e;
}

}  // namespace example
