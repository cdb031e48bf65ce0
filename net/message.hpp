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

// Its size on the air, above the MAC, as a robot would pack it: a header (message type and
// version, 2 bytes; entry count, 2 bytes) and one entry per robot state it carries (the
// sender's own: id 4, sequence number 8, send time 8, virtual generator 16 and position 16
// bytes). A simulated radio (ns3_wifi) transmits this many bytes; the abstract channel
// ignores sizes.
inline constexpr std::uint32_t kMessageHeaderBytes = 4;
inline constexpr std::uint32_t kStateEntryBytes = 4 + 8 + 8 + 16 + 16;
inline constexpr std::uint32_t kStateMessageBytes = kMessageHeaderBytes + kStateEntryBytes;

}  // namespace covsim
