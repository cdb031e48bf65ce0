#include "net/uniform_delay.hpp"

#include <fmt/format.h>

namespace covsim {

DelayEntry uniform_delay_entry() {
  DelayEntry e;
  e.name = "uniform";
  e.description = "a delay drawn uniformly between min and max";
  e.params = {ParamSpec::number("min", "s", "the least delay").at_least(0),
              ParamSpec::number("max", "s", "the largest delay (>= min)").at_least(0)};
  e.make = [](const Params& p) {
    const double lo = p.number("min"), hi = p.number("max");
    if (hi < lo) throw ParamError("max", fmt::format("expected max >= min ({}), found {}", lo, hi));
    return std::make_shared<const UniformDelay>(lo, hi);
  };
  return e;
}

}  // namespace covsim
