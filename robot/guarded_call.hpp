#pragma once
// A call into one robot's component (its law, planner or collision avoidance): what the
// component throws becomes a ComponentError naming the robot, the component and the time,
// the cause nested.
#include <fmt/format.h>

#include <cstdint>
#include <exception>
#include <string_view>

#include "core/sim_time.hpp"
#include "robot/component_error.hpp"

namespace covsim {

template <class F>
auto guarded_call(std::uint32_t robot, std::string_view role, std::string_view name, SimTime now,
                  F&& f) {
  try {
    return f();
  } catch (const ComponentError&) {
    throw;
  } catch (const std::exception& e) {
    std::throw_with_nested(ComponentError(
        fmt::format("robot {}'s {} \"{}\" at t = {} s", robot, role, name, now.seconds()),
        e.what()));
  }
}

}  // namespace covsim
