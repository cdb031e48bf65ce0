#pragma once
// A delay of base plus an exponential jitter of the given mean.
#include "net/delay_model.hpp"

namespace covsim {

class ExponentialDelay final : public DelayModel {
 public:
  ExponentialDelay(double base, double mean) : base_(base), mean_(mean) {}
  double sample(RandomStream& rng) const override { return base_ + rng.exponential(mean_); }
  double minimum() const override { return base_; }

 private:
  double base_, mean_;
};

DelayEntry exponential_delay_entry();

}  // namespace covsim
