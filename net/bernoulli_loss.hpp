#pragma once
// Each message is lost with probability p, independently.
#include "net/loss_model.hpp"

namespace covsim {

class BernoulliLoss final : public LossModel {
 public:
  explicit BernoulliLoss(double p) : p_(p) {}
  bool lost(LinkState&, RandomStream& rng, double) const override { return rng.bernoulli(p_); }

 private:
  double p_;
};

LossEntry bernoulli_loss_entry();

}  // namespace covsim
