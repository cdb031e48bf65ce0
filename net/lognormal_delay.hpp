#pragma once
// A delay of base plus exp(N(mu, sigma²)).
#include "net/delay_model.hpp"

namespace covsim {

class LogNormalDelay final : public DelayModel {
 public:
  LogNormalDelay(double base, double mu, double sigma) : base_(base), mu_(mu), sigma_(sigma) {}
  double sample(RandomStream& rng) const override { return base_ + rng.lognormal(mu_, sigma_); }
  double minimum() const override { return base_; }

 private:
  double base_, mu_, sigma_;
};

DelayEntry lognormal_delay_entry();

}  // namespace covsim
