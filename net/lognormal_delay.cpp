#include "net/lognormal_delay.hpp"

namespace covsim {

DelayEntry lognormal_delay_entry() {
  DelayEntry e;
  e.name = "lognormal";
  e.description = "base plus a log-normal jitter exp(N(mu, sigma^2))";
  e.params = {ParamSpec::number("base", "s", "the least delay").at_least(0),
              ParamSpec::number("mu", "", "mean of the jitter's logarithm (of seconds)"),
              ParamSpec::number("sigma", "", "standard deviation of the jitter's logarithm")
                  .at_least(0)};
  e.make = [](const Params& p) {
    return std::make_shared<const LogNormalDelay>(p.number("base"), p.number("mu"),
                                                  p.number("sigma"));
  };
  return e;
}

}  // namespace covsim
