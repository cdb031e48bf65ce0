#include "robot/virtual_generators_law.hpp"

namespace covsim {

Vec2 VirtualGeneratorsLaw::target(const Robot&, const Knowledge& k) {
  return own_cell_summary(integrator_, k).centroid;
}

bool VirtualGeneratorsLaw::at_rest(const Robot& r, const Tolerances& t) const {
  return distance(r.virtual_target, r.virtual_generator) <= t.virtual_generator;
}

LawEntry virtual_generators_entry() {
  LawEntry e;
  e.name = "virtual_generators";
  e.description =
      "the paper's: Lloyd on virtual generators that move as if Ω were convex; real targets "
      "projected onto Ω";
  e.contract.lloyd = true;
  e.make = [](const LawContext& ctx, const Params&) {
    return std::make_unique<VirtualGeneratorsLaw>(ctx.integrator);
  };
  return e;
}

}  // namespace covsim
