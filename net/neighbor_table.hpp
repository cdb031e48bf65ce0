#pragma once
// What a robot last heard from each other robot. Messages may arrive out of order: an
// entry is replaced only by a newer sequence number. Entries whose information is older
// than the staleness limit (by send time) are dropped. Entries are kept in a vector sorted
// by sender: a robot hears a few dozen neighbours, and a delivery is a binary search.
#include <cstdint>
#include <span>
#include <vector>

#include "net/message.hpp"

namespace covsim {

class NeighborTable {
 public:
  // Returns false (and keeps the entry) when the message is not newer than what is held.
  bool update(const StateMessage& m);
  // Drops entries sent before now - staleness.
  void drop_stale(SimTime now, SimTime staleness);
  // By sender id, increasing.
  std::span<const StateMessage> entries() const { return entries_; }
  // The entry from that sender, or null.
  const StateMessage* find(std::uint32_t sender) const;
  std::size_t size() const { return entries_.size(); }
  // The age of each entry's information at `now`, in seconds.
  std::vector<double> ages(SimTime now) const;

 private:
  std::vector<StateMessage> entries_;
};

}  // namespace covsim
