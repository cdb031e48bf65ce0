#pragma once
// Small hand-built configurations for the coverage laws' unit tests, with answers worked out
// by hand: two robots in a unit square split it into halves (a vertical bisector), whose
// centroids are known exactly.
#include <vector>

#include "geometry/environment.hpp"
#include "geometry/uniform_density.hpp"
#include "robot/coverage_law.hpp"
#include "robot/generator_state.hpp"
#include "robot/ideal_view.hpp"

namespace covsim::test {

inline Environment unit_square() {
  return Environment({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {});
}

// The unit square with a 0.2 m square hole in its middle: the left half's area is
// 0.5 - 0.02 and its centroid x = (0.5 · 0.25 - 0.02 · 0.45) / 0.48.
inline Environment square_with_hole() {
  return Environment({{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                     {{{0.4, 0.4}, {0.4, 0.6}, {0.6, 0.6}, {0.6, 0.4}}});
}
inline constexpr double kHoledHalfCentroidX = (0.5 * 0.25 - 0.02 * 0.45) / 0.48;

inline Robot robot_at(std::uint32_t id, Vec2 p) {
  Robot r;
  r.id = id;
  r.position = r.virtual_generator = r.virtual_target = r.real_target = p;
  return r;
}

// What robot i knows: everything, through a shared state (the ideal network), or only the
// points given, computing its own cell (a networked robot).
struct Shared {
  Shared(const Environment& env, std::vector<Vec2> points)
      : integrator(env, density), state(integrator, points), view(state) {}
  Knowledge knowledge(std::uint32_t i, Generators kind) const { return view.knowledge(i, kind); }
  UniformDensity density;
  CellIntegrator integrator;
  GeneratorState state;
  IdealView view;
};

inline Knowledge own(const std::vector<Vec2>& points, std::size_t self, Generators kind) {
  return Knowledge{points, self, kind, nullptr, std::nullopt, nullptr};
}

}  // namespace covsim::test
