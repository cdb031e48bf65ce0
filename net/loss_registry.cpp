#include "net/loss_registry.hpp"

#include "net/bernoulli_loss.hpp"
#include "net/distance_loss.hpp"
#include "net/gilbert_elliott_loss.hpp"
#include "net/no_loss.hpp"

namespace covsim {

Registry<LossEntry>& loss_registry() {
  static Registry<LossEntry> registry("loss model",
                                      {no_loss_entry(), bernoulli_loss_entry(),
                                       gilbert_elliott_loss_entry(), distance_loss_entry()});
  return registry;
}

}  // namespace covsim
