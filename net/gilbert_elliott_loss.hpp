#pragma once
// Bursty loss: each directed link is in a good or a bad state, stepping once per message
// (good -> bad with p_good_to_bad, bad -> good with p_bad_to_good) before the loss draw with
// that state's probability. Long-run loss:
// (p_bad_to_good loss_good + p_good_to_bad loss_bad) / (p_good_to_bad + p_bad_to_good).
#include "net/loss_model.hpp"

namespace covsim {

class GilbertElliottLoss final : public LossModel {
 public:
  GilbertElliottLoss(double p_good_to_bad, double p_bad_to_good, double loss_good,
                     double loss_bad)
      : p_good_to_bad_(p_good_to_bad),
        p_bad_to_good_(p_bad_to_good),
        loss_good_(loss_good),
        loss_bad_(loss_bad) {}
  bool lost(LinkState& link, RandomStream& rng, double) const override;
  // The long-run fraction of messages lost.
  double stationary_loss() const;

 private:
  double p_good_to_bad_, p_bad_to_good_, loss_good_, loss_bad_;
};

LossEntry gilbert_elliott_loss_entry();

}  // namespace covsim
