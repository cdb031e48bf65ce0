#pragma once
// What a planner's step says about the motion, and its names as records write them
// (final.json's robots, the Python planners' steps).
#include <array>
#include <string>
#include <string_view>

namespace covsim {

enum class PlanStatus {
  moving,     // on the way
  reached,    // at the goal
  projected,  // the goal is unreachable; settled at the closest reachable boundary point
  stalled,    // gave up (no progress, or the path budget ran out)
};
inline constexpr std::array kPlanStatuses{PlanStatus::moving, PlanStatus::reached,
                                          PlanStatus::projected, PlanStatus::stalled};

std::string_view to_string(PlanStatus s);
// Every status's name, for messages: "moving, reached, projected or stalled".
std::string plan_status_names();
// The status of that name; throws std::invalid_argument naming the ones there are.
PlanStatus status_named(std::string_view name);

inline bool is_settled(PlanStatus s) {
  return s != PlanStatus::moving;
}

}  // namespace covsim
