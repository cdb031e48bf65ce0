#include "net/gilbert_elliott_loss.hpp"

namespace covsim {

bool GilbertElliottLoss::lost(LinkState& link, RandomStream& rng, double) const {
  const bool bad = link.state != 0 ? !rng.bernoulli(p_bad_to_good_) : rng.bernoulli(p_good_to_bad_);
  link.state = bad ? 1 : 0;
  return rng.bernoulli(bad ? loss_bad_ : loss_good_);
}

double GilbertElliottLoss::stationary_loss() const {
  const double s = p_good_to_bad_ + p_bad_to_good_;
  const double bad = s > 0.0 ? p_good_to_bad_ / s : 0.0;
  return (1.0 - bad) * loss_good_ + bad * loss_bad_;
}

LossEntry gilbert_elliott_loss_entry() {
  const auto probability = [](const char* name, const char* what) {
    return ParamSpec::number(name, "", what).at_least(0).at_most(1);
  };
  LossEntry e;
  e.name = "gilbert_elliott";
  e.description = "bursty loss: a good/bad Markov state per link, stepped once per message";
  e.params = {probability("p_good_to_bad", "probability of going from good to bad"),
              probability("p_bad_to_good", "probability of going from bad to good"),
              probability("loss_good", "loss probability in the good state"),
              probability("loss_bad", "loss probability in the bad state")};
  e.make = [](const Params& p) {
    return std::make_shared<const GilbertElliottLoss>(p.number("p_good_to_bad"),
                                                      p.number("p_bad_to_good"),
                                                      p.number("loss_good"), p.number("loss_bad"));
  };
  return e;
}

}  // namespace covsim
