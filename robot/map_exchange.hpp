#pragma once
// The map part of a robot's broadcasts (robot/mapping.hpp), as the networked view carries it:
// what a sender packs into a message, and what a receiver merges from one it hears.
#include <cstdint>

#include "net/message.hpp"

namespace covsim {

class MapExchange {
 public:
  virtual ~MapExchange() = default;
  virtual MapPayload pack(std::uint32_t sender) = 0;
  virtual void merge(std::uint32_t receiver, const MapPayload& payload) = 0;
  // The most map bytes one broadcast carries.
  virtual std::uint64_t payload_limit() const = 0;
};

}  // namespace covsim
