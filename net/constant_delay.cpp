#include "net/constant_delay.hpp"

namespace covsim {

DelayEntry constant_delay_entry() {
  DelayEntry e;
  e.name = "constant";
  e.description = "every message takes the same time";
  e.params = {ParamSpec::number("value", "s", "the delay").at_least(0)};
  e.make = [](const Params& p) { return std::make_shared<const ConstantDelay>(p.number("value")); };
  return e;
}

}  // namespace covsim
