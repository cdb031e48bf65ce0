#pragma once
// What a robot broadcasts: its state as of the send time.
#include <cstdint>
#include <memory>
#include <vector>

#include "core/sim_time.hpp"
#include "core/vec2.hpp"

namespace covsim {

// The map readings a broadcast carries (robot/mapping.hpp): their run-wide numbers, and their
// size on the air (beside the state entry).
struct MapPayload {
  std::shared_ptr<const std::vector<std::uint32_t>> scans;
  std::uint32_t bytes = 0;
};

struct StateMessage {
  std::uint32_t sender = 0;
  std::uint64_t seq = 0;  // per sender, increasing
  SimTime sent;
  Vec2 virtual_generator;
  Vec2 position;
  MapPayload map;  // robots that map Ω: readings of the sender's map
};

// Its size on the air, above the MAC, as a robot would pack it: a header (message type and
// version, 2 bytes; entry count, 2 bytes) and one entry per robot state it carries (the
// sender's own: id 4, sequence number 8, send time 8, virtual generator 16 and position 16
// bytes). A simulated radio (ns3_wifi) transmits this many bytes; the abstract channel
// ignores sizes.
inline constexpr std::uint32_t kMessageHeaderBytes = 4;
inline constexpr std::uint32_t kStateEntryBytes = 4 + 8 + 8 + 16 + 16;
inline constexpr std::uint32_t kStateMessageBytes = kMessageHeaderBytes + kStateEntryBytes;
// The largest message a simulated radio carries whole: 802.11's largest MSDU.
inline constexpr std::uint32_t kMaxRadioMessageBytes = 2304;

}  // namespace covsim
