#include "core/config_key.hpp"

namespace covsim {

static_assert(kMinPeriod == 1e-4 && kMaxPeriod == 1e6, "the words below state the limits");

ParamSpec period_param(std::string name, std::string description) {
  return ParamSpec::number(std::move(name), "s", std::move(description))
      .at_least(kMinPeriod)
      .at_most(kMaxPeriod)
      .worded("a period between 0.0001 and 1e6 s");
}

ParamSpec duration_param(std::string name, std::string description) {
  return ParamSpec::number(std::move(name), "s", std::move(description))
      .at_least(0)
      .at_most(kMaxPeriod)
      .worded("a non-negative number of seconds, at most 1e6");
}

}  // namespace covsim
