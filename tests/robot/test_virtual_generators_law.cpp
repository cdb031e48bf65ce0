// The paper's law (robot/virtual_generators_law): Lloyd on the virtual generators, which may
// lie outside Ω; a robot is at rest once its virtual generator rests on its target.
#include <catch2/catch.hpp>

#include "robot/virtual_generators_law.hpp"
#include "tests/robot/law_cases.hpp"

using namespace covsim;
using namespace covsim::test;

TEST_CASE("the paper's law targets the centroids of the virtual generators' cells", "[law]") {
  const Environment env = unit_square();
  // The virtual generators split the square into halves; the real positions, elsewhere, do
  // not count.
  Shared shared(env, {{0.5, 0.5}, {0.6, 0.5}});
  shared.state.move(Generators::virtual_generators, 0, {0.2, 0.3});
  shared.state.move(Generators::virtual_generators, 1, {0.8, 0.3});
  VirtualGeneratorsLaw law(shared.integrator);
  CHECK(law.generators() == Generators::virtual_generators);
  CHECK(law.moves_virtual_generators());
  const Vec2 want[] = {{0.25, 0.5}, {0.75, 0.5}};
  for (std::uint32_t i = 0; i < 2; ++i) {
    INFO("robot " << i);
    const Vec2 t =
        law.target(robot_at(i, {0.5, 0.5}), shared.knowledge(i, Generators::virtual_generators));
    CHECK(t.x == Approx(want[i].x).epsilon(0).margin(1e-12));
    CHECK(t.y == Approx(want[i].y).epsilon(0).margin(1e-12));
  }
}

TEST_CASE("a virtual generator outside Ω still owns the part of Ω its cell covers", "[law]") {
  // Generators (0.5, 0.25) and (0.5, 1.5): the bisector y = 0.875 leaves the upper one the
  // strip above it, centroid (0.5, 0.9375), and the lower one the rest, (0.5, 0.4375).
  const Environment env = unit_square();
  const std::vector<Vec2> g{{0.5, 0.25}, {0.5, 1.5}};
  const UniformDensity density;
  const CellIntegrator integrator(env, density);
  VirtualGeneratorsLaw law(integrator);
  const Vec2 low = law.target(robot_at(0, g[0]), own(g, 0, Generators::virtual_generators));
  const Vec2 high = law.target(robot_at(1, g[1]), own(g, 1, Generators::virtual_generators));
  CHECK(low.y == Approx(0.4375).epsilon(0).margin(1e-12));
  CHECK(high.y == Approx(0.9375).epsilon(0).margin(1e-12));
  CHECK(high.x == Approx(0.5).epsilon(0).margin(1e-12));
}

TEST_CASE("the paper's law is at rest only with the virtual generator on its target", "[law]") {
  const Environment env = square_with_hole();
  const std::vector<Vec2> g{{0.2, 0.5}, {0.8, 0.5}};
  const UniformDensity density;
  const CellIntegrator integrator(env, density);
  VirtualGeneratorsLaw law(integrator);
  Robot r = robot_at(0, g[0]);
  r.virtual_target = law.target(r, own(g, 0, Generators::virtual_generators));
  CHECK(r.virtual_target.x == Approx(kHoledHalfCentroidX).epsilon(0).margin(1e-12));
  const Tolerances tol{1e-3, 0.01};
  CHECK_FALSE(law.at_rest(r, tol));  // 0.042 m away
  r.virtual_generator = r.virtual_target + Vec2{0.0, 0.009};
  CHECK(law.at_rest(r, tol));
  r.virtual_generator = r.virtual_target + Vec2{0.0, 0.011};
  CHECK_FALSE(law.at_rest(r, tol));
}
