#include "core/config_key.hpp"

namespace covsim {

ParamSpec period_param(std::string name, std::string description) {
  return ParamSpec::number(std::move(name), "s", std::move(description))
      .at_least(kMinPeriod)
      .at_most(kMaxPeriod);
}

ParamSpec duration_param(std::string name, std::string description) {
  return ParamSpec::number(std::move(name), "s", std::move(description))
      .at_least(0)
      .at_most(kMaxPeriod);
}

}  // namespace covsim
