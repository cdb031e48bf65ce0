#pragma once
// A networked robot's own cell and its moments, kept with the generators they were computed
// from. Loop 1 recomputes from the robot's table as it is, which often has not changed
// since the last time: a Lloyd period shorter than the broadcast period, or neighbours
// that have settled. Then the cell comes from here instead of a new triangulation of the
// table; the same generators, bit for bit, give the same cell, so runs are unchanged.
#include <cstddef>
#include <span>
#include <vector>

#include "geometry/cell_integrator.hpp"
#include "geometry/convex_polygon.hpp"

namespace covsim {

class OwnCellCache {
 public:
  // The cell and summary stored for exactly these generators (bit patterns), self and
  // integrator, if the last store was for them.
  const ConvexPolygon* find(const CellIntegrator& integrator, std::span<const Vec2> generators,
                            std::size_t self, CellSummary& summary) const;
  void store(const CellIntegrator& integrator, std::span<const Vec2> generators, std::size_t self,
             const ConvexPolygon& cell, const CellSummary& summary);

 private:
  const CellIntegrator* integrator_ = nullptr;
  std::vector<Vec2> generators_;
  std::size_t self_ = 0;
  bool valid_ = false;
  ConvexPolygon cell_;
  CellSummary summary_;
};

}  // namespace covsim
