#pragma once
// A delay drawn uniformly from [min, max].
#include "net/delay_model.hpp"

namespace covsim {

class UniformDelay final : public DelayModel {
 public:
  UniformDelay(double min, double max) : min_(min), max_(max) {}
  double sample(RandomStream& rng) const override { return rng.uniform(min_, max_); }
  double minimum() const override { return min_; }

 private:
  double min_, max_;
};

DelayEntry uniform_delay_entry();

}  // namespace covsim
