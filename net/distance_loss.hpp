#pragma once
// Loss that grows with the link's length d: p(d) = min(1, p_min + (1 - p_min)(d/d_max)^exponent).
#include "net/loss_model.hpp"

namespace covsim {

class DistanceLoss final : public LossModel {
 public:
  DistanceLoss(double p_min, double d_max, double exponent)
      : p_min_(p_min), d_max_(d_max), exponent_(exponent) {}
  bool lost(LinkState&, RandomStream& rng, double distance) const override {
    return rng.bernoulli(at(distance));
  }
  double at(double d) const;

 private:
  double p_min_, d_max_, exponent_;
};

LossEntry distance_loss_entry();

}  // namespace covsim
