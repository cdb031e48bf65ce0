#include "net/neighbor_table.hpp"

#include <algorithm>

namespace covsim {

namespace {
bool by_sender(const StateMessage& e, std::uint32_t sender) {
  return e.sender < sender;
}
}  // namespace

bool NeighborTable::update(const StateMessage& m) {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), m.sender, by_sender);
  if (it == entries_.end() || it->sender != m.sender) {
    entries_.insert(it, m);
    return true;
  }
  if (m.seq <= it->seq) return false;
  *it = m;
  return true;
}

const StateMessage* NeighborTable::find(std::uint32_t sender) const {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), sender, by_sender);
  return it != entries_.end() && it->sender == sender ? &*it : nullptr;
}

void NeighborTable::drop_stale(SimTime now, SimTime staleness) {
  std::erase_if(entries_, [&](const StateMessage& e) { return now - e.sent > staleness; });
}

std::vector<double> NeighborTable::ages(SimTime now) const {
  std::vector<double> out;
  out.reserve(entries_.size());
  for (const StateMessage& e : entries_)
    out.push_back((now - e.sent).seconds());
  return out;
}

}  // namespace covsim
