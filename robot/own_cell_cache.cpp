#include "robot/own_cell_cache.hpp"

#include <cstring>

namespace covsim {

const ConvexPolygon* OwnCellCache::find(const CellIntegrator& integrator,
                                        std::span<const Vec2> generators, std::size_t self,
                                        CellSummary& summary) const {
  // Bit patterns, not values: -0.0 and 0.0 could clip differently.
  if (!valid_ || &integrator != integrator_ || self != self_ ||
      generators.size() != generators_.size() ||
      std::memcmp(generators.data(), generators_.data(), generators.size_bytes()) != 0)
    return nullptr;
  summary = summary_;
  return &cell_;
}

void OwnCellCache::store(const CellIntegrator& integrator, std::span<const Vec2> generators,
                         std::size_t self, const ConvexPolygon& cell, const CellSummary& summary) {
  integrator_ = &integrator;
  generators_.assign(generators.begin(), generators.end());
  self_ = self;
  cell_ = cell;
  summary_ = summary;
  valid_ = true;
}

}  // namespace covsim
