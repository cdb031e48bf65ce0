#include "net/exponential_delay.hpp"

namespace covsim {

DelayEntry exponential_delay_entry() {
  DelayEntry e;
  e.name = "exponential";
  e.description = "base plus an exponentially distributed jitter";
  e.params = {ParamSpec::number("base", "s", "the least delay").at_least(0),
              ParamSpec::number("mean", "s", "mean of the jitter").at_least(0)};
  e.make = [](const Params& p) {
    return std::make_shared<const ExponentialDelay>(p.number("base"), p.number("mean"));
  };
  return e;
}

}  // namespace covsim
