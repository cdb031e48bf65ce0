#include "net/no_loss.hpp"

namespace covsim {

LossEntry no_loss_entry() {
  LossEntry e;
  e.name = "none";
  e.description = "every message arrives";
  e.make = [](const Params&) { return std::make_shared<const NoLoss>(); };
  return e;
}

}  // namespace covsim
