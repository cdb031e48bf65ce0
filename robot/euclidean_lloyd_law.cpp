#include "robot/euclidean_lloyd_law.hpp"

namespace covsim {

Vec2 EuclideanLloydLaw::target(const Robot&, const Knowledge& k) {
  return own_cell_summary(integrator_, k).centroid;
}

LawEntry euclidean_lloyd_entry() {
  LawEntry e;
  e.name = "euclidean_lloyd";
  e.description = "Lloyd on the real positions: each robot drives at its cell's centroid";
  e.contract.lloyd = true;
  e.make = [](const LawContext& ctx, const Params&) {
    return std::make_unique<EuclideanLloydLaw>(ctx.integrator);
  };
  return e;
}

}  // namespace covsim
