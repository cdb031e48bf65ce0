#include "net/distance_loss.hpp"

#include <algorithm>
#include <cmath>

namespace covsim {

double DistanceLoss::at(double d) const {
  return std::min(1.0, p_min_ + (1.0 - p_min_) * std::pow(d / d_max_, exponent_));
}

LossEntry distance_loss_entry() {
  LossEntry e;
  e.name = "distance";
  e.description = "loss rising with the link's length, certain beyond d_max";
  e.params = {ParamSpec::number("p_min", "", "loss probability at distance 0").at_least(0).at_most(1),
              ParamSpec::number("d_max", "m", "length at which a message is always lost")
                  .greater_than(0),
              ParamSpec::number("exponent", "", "shape of the rise").greater_than(0)};
  e.make = [](const Params& p) {
    return std::make_shared<const DistanceLoss>(p.number("p_min"), p.number("d_max"),
                                                p.number("exponent"));
  };
  return e;
}

}  // namespace covsim
