#include "robot/coverage_law.hpp"

#include "robot/generator_state.hpp"

namespace covsim {

bool CoverageLaw::at_rest(const Robot&, const Tolerances&) const {
  return true;
}

const VoronoiPartition* Knowledge::partition() const {
  if (integrator != nullptr) return believed;
  return shared != nullptr ? &shared->partition(kind) : nullptr;
}

CellSummary own_cell_summary(const CellIntegrator& law_integrator, const Knowledge& k,
                             ConvexPolygon* cell) {
  const CellIntegrator& integrator = k.integrator != nullptr ? *k.integrator : law_integrator;
  if (const VoronoiPartition* p = k.partition()) {
    if (cell != nullptr) cell->assign(p->cell(k.self).begin(), p->cell(k.self).end());
    return p->summary(k.self);
  }
  CellSummary s;
  if (k.cache != nullptr) {
    if (const ConvexPolygon* kept = k.cache->find(integrator, k.points, k.self, s)) {
      if (cell != nullptr) *cell = *kept;
      return s;
    }
  }
  const Vec2 g = k.points[k.self];
  ConvexPolygon local;
  voronoi_cell(integrator, k.points, k.self, local);
  s = summarize(integrator.integrate(local, g), g);
  if (k.cache != nullptr) k.cache->store(integrator, k.points, k.self, local, s);
  if (cell != nullptr) *cell = std::move(local);
  return s;
}

}  // namespace covsim
