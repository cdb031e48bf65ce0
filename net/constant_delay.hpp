#pragma once
// Every message takes the same time.
#include "net/delay_model.hpp"

namespace covsim {

class ConstantDelay final : public DelayModel {
 public:
  explicit ConstantDelay(double value) : value_(value) {}
  double sample(RandomStream&) const override { return value_; }
  double minimum() const override { return value_; }
  bool instantaneous() const override { return value_ == 0.0; }

 private:
  double value_;
};

DelayEntry constant_delay_entry();

}  // namespace covsim
