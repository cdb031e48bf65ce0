#include "net/bernoulli_loss.hpp"

namespace covsim {

LossEntry bernoulli_loss_entry() {
  LossEntry e;
  e.name = "bernoulli";
  e.description = "each message lost with probability p, independently";
  e.params = {ParamSpec::number("p", "", "loss probability").at_least(0).at_most(1)};
  e.make = [](const Params& p) { return std::make_shared<const BernoulliLoss>(p.number("p")); };
  return e;
}

}  // namespace covsim
