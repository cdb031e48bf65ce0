#pragma once
// Every message arrives.
#include "net/loss_model.hpp"

namespace covsim {

class NoLoss final : public LossModel {
 public:
  bool lost(LinkState&, RandomStream&, double) const override { return false; }
  bool lossless() const override { return true; }
};

LossEntry no_loss_entry();

}  // namespace covsim
