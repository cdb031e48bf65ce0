#pragma once
// What a robot broadcasts: its state as of the send time.
#include <cstdint>

#include "core/sim_time.hpp"
#include "core/vec2.hpp"

namespace covsim {

struct StateMessage {
  std::uint32_t sender = 0;
  std::uint64_t seq = 0;  // per sender, increasing
  SimTime sent;
  Vec2 virtual_generator;
  Vec2 position;
};

}  // namespace covsim
