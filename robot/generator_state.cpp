#include "robot/generator_state.hpp"

#include <utility>

namespace covsim {

GeneratorState::GeneratorState(const CellIntegrator& integrator, const std::vector<Vec2>& starts)
    : integrator_(integrator) {
  for (Kind& k : kinds_)
    k.points = starts;
}

void GeneratorState::move(Generators k, std::uint32_t i, Vec2 p) {
  Kind& kind = kinds_[static_cast<std::size_t>(k)];
  if (kind.points[i] == p) return;
  kind.points[i] = p;
  ++kind.version;
}

const VoronoiPartition& GeneratorState::partition(Generators k) const {
  const Kind& kind = this->kind(k);
  if (!kind.partition) {
    kind.partition.emplace(integrator_, kind.points, VoronoiPartition::Coincident::split);
  } else if (kind.partition_version != kind.version) {
    // Cells away from the generators that moved are kept from the last partition.
    VoronoiPartition next(integrator_, kind.points, VoronoiPartition::Coincident::split,
                          std::move(*kind.partition));
    kind.partition.reset();
    kind.partition.emplace(std::move(next));
  }
  kind.partition_version = kind.version;
  return *kind.partition;
}

}  // namespace covsim
