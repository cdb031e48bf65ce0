#include "planners/plan_status.hpp"

#include <stdexcept>

namespace covsim {

std::string_view to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::moving:
      return "moving";
    case PlanStatus::reached:
      return "reached";
    case PlanStatus::projected:
      return "projected";
    case PlanStatus::stalled:
      return "stalled";
  }
  return "unknown";
}

std::string plan_status_names() {
  std::string out;
  for (std::size_t i = 0; i < kPlanStatuses.size(); ++i) {
    out += i == 0 ? "" : i + 1 == kPlanStatuses.size() ? " or " : ", ";
    out += to_string(kPlanStatuses[i]);
  }
  return out;
}

PlanStatus status_named(std::string_view name) {
  for (PlanStatus s : kPlanStatuses) {
    if (to_string(s) == name) return s;
  }
  throw std::invalid_argument("expected " + plan_status_names() + ", found \"" + std::string(name) +
                              "\"");
}

}  // namespace covsim
