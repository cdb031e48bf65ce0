#include "net/neighbor_table.hpp"

namespace covsim {

bool NeighborTable::update(const StateMessage& m) {
  auto [it, inserted] = entries_.try_emplace(m.sender, m);
  if (inserted) return true;
  if (m.seq <= it->second.seq) return false;
  it->second = m;
  return true;
}

void NeighborTable::drop_stale(SimTime now, SimTime staleness) {
  std::erase_if(entries_, [&](const auto& e) { return now - e.second.sent > staleness; });
}

std::vector<double> NeighborTable::ages(SimTime now) const {
  std::vector<double> out;
  for (const auto& [sender, m] : entries_)
    out.push_back((now - m.sent).seconds());
  return out;
}

}  // namespace covsim
