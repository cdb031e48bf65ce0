// The ideal network (robot/ideal_view): every robot knows every generator as it is now, at
// once, and shares one partition with the others.
#include <catch2/catch.hpp>

#include "geometry/uniform_density.hpp"
#include "robot/ideal_view.hpp"

using namespace covsim;

TEST_CASE("the ideal view gives every robot every generator as it is now", "[view]") {
  const Environment square({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {});
  const UniformDensity density;
  const CellIntegrator integrator(square, density);
  GeneratorState state(integrator, {{0.2, 0.2}, {0.8, 0.2}, {0.5, 0.8}});
  IdealView view(state);
  CHECK_FALSE(view.decentralized());
  view.start(SimTime::zero());
  for (std::uint32_t i = 0; i < 3; ++i) {
    CHECK(view.ready(i));  // nothing to acquire
    const Knowledge k = view.knowledge(i, Generators::positions);
    CHECK(k.self == i);
    CHECK(k.points == state.points(Generators::positions));
    CHECK(k.shared == &state);
    CHECK(k.version == state.version(Generators::positions));
    REQUIRE(k.partition() != nullptr);
    CHECK(k.partition() == &state.partition(Generators::positions));  // one for everybody
  }
  // A move is known to everybody at once, under a new version; the other kind is untouched.
  const std::uint64_t before = state.version(Generators::positions);
  state.move(Generators::positions, 1, {0.7, 0.3});
  const Knowledge k0 = view.knowledge(0, Generators::positions);
  CHECK(k0.points[1] == Vec2{0.7, 0.3});
  CHECK(*k0.version != before);
  const Knowledge v0 = view.knowledge(0, Generators::virtual_generators);
  CHECK(v0.points[1] == Vec2{0.8, 0.2});
  CHECK(v0.kind == Generators::virtual_generators);
  // The shared partition follows: robot 1's cell is the new generator's.
  CHECK(k0.partition()->generators()[1] == Vec2{0.7, 0.3});
  CHECK(view.totals().sent == 0);  // no message is simulated
}
