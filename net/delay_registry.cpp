#include "net/delay_registry.hpp"

#include "net/constant_delay.hpp"
#include "net/exponential_delay.hpp"
#include "net/lognormal_delay.hpp"
#include "net/uniform_delay.hpp"

namespace covsim {

Registry<DelayEntry>& delay_registry() {
  static Registry<DelayEntry> registry("delay model",
                                       {constant_delay_entry(), uniform_delay_entry(),
                                        exponential_delay_entry(), lognormal_delay_entry()});
  return registry;
}

}  // namespace covsim
