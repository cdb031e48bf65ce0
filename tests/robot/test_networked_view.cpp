// The networked view (robot/networked_view) on its own: a robot knows what has been
// delivered to it and nothing else; entries go stale; a robot acquires its neighbours before
// its first loop 1, or goes alone after the timeout.
#include <catch2/catch.hpp>

#include <memory>

#include "core/kernel.hpp"
#include "geometry/uniform_density.hpp"
#include "net/constant_delay.hpp"
#include "robot/networked_view.hpp"

using namespace covsim;

namespace {
SimTime at(double seconds) {
  return SimTime::from_seconds(seconds);
}

// Three robots in a 4 m square: 0 and 1 close together, 2 in the far corner. A 1 m range
// lets 0 and 1 hear each other and nobody hear 2.
struct World {
  Environment square{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}};
  UniformDensity density;
  CellIntegrator integrator{square, density};
  GeneratorState state{integrator, {{0.5, 0.5}, {1.0, 0.5}, {3.5, 3.5}}};
  Kernel kernel{42};
};

NetworkConfig network_with_range(double range) {
  NetworkConfig c;
  c.channel.range = range;
  return c;
}
}  // namespace

TEST_CASE("a networked robot knows only what was delivered to it", "[view]") {
  World w;
  NetworkedView view(w.kernel, w.square, network_with_range(1.0), w.state);
  CHECK(view.decentralized());
  // Before any message: itself alone, at its place in id order.
  for (std::uint32_t i = 0; i < 3; ++i) {
    const Knowledge k = view.knowledge(i, Generators::positions);
    REQUIRE(k.points.size() == 1);
    CHECK(k.self == 0);
    CHECK(k.points[0] == w.state.points(Generators::positions)[i]);
    CHECK(k.shared == nullptr);  // its own cell, not a shared partition
    CHECK_FALSE(k.version);
    CHECK(k.cache != nullptr);
  }
  view.start(SimTime::zero());
  w.kernel.run_until(SimTime::zero());  // the first broadcasts, delivered at once
  Knowledge k1 = view.knowledge(1, Generators::positions);
  REQUIRE(k1.points.size() == 2);
  CHECK(k1.self == 1);  // after robot 0, in id order
  CHECK(k1.points[0] == Vec2{0.5, 0.5});
  CHECK(view.knowledge(2, Generators::positions).points.size() == 1);  // out of range
  // Each broadcast is a link transmission to each of the two others; the far robot's links
  // are out of range both ways.
  CHECK(view.totals().sent == 6);
  CHECK(view.totals().delivered == 2);
  CHECK(view.totals().unreachable == 4);
  // Robot 0 moves: robot 1 learns it at the next broadcast, not before.
  w.state.move(Generators::positions, 0, {0.6, 0.5});
  view.moved(0);
  w.kernel.run_until(at(0.05));
  CHECK(view.knowledge(1, Generators::positions).points[0] == Vec2{0.5, 0.5});
  w.kernel.run_until(at(0.1));
  CHECK(view.knowledge(1, Generators::positions).points[0] == Vec2{0.6, 0.5});
  // The message carries both generators: the virtual one as it was sent.
  w.state.move(Generators::virtual_generators, 0, {0.7, 0.7});
  w.kernel.run_until(at(0.15));
  CHECK(view.knowledge(1, Generators::virtual_generators).points[0] == Vec2{0.5, 0.5});
  w.kernel.run_until(at(0.2));
  CHECK(view.knowledge(1, Generators::virtual_generators).points[0] == Vec2{0.7, 0.7});
  CHECK(view.knowledge(1, Generators::positions).points[0] == Vec2{0.6, 0.5});
  // Its own generator is always its current one.
  w.state.move(Generators::positions, 1, {1.1, 0.6});
  CHECK(view.knowledge(1, Generators::positions).points[1] == Vec2{1.1, 0.6});
}

TEST_CASE("a delayed message is known when it is delivered", "[view]") {
  World w;
  NetworkConfig c = network_with_range(1.0);
  c.channel.delay = std::make_shared<const ConstantDelay>(0.03);
  NetworkedView view(w.kernel, w.square, c, w.state);
  view.start(SimTime::zero());
  w.kernel.run_until(at(0.029));
  CHECK(view.knowledge(0, Generators::positions).points.size() == 1);
  w.kernel.run_until(at(0.03));
  CHECK(view.knowledge(0, Generators::positions).points.size() == 2);
}

TEST_CASE("entries older than the staleness limit are dropped at the robot's refresh", "[view]") {
  World w;
  NetworkConfig c = network_with_range(1.0);
  c.staleness = at(0.25);
  NetworkedView view(w.kernel, w.square, c, w.state);
  view.start(SimTime::zero());
  w.kernel.run_until(at(0.3));
  // Robot 1 walks out of range after its broadcast at 0.3: robot 0 keeps that entry ...
  w.state.move(Generators::positions, 1, {2.5, 0.5});
  view.moved(1);
  w.kernel.run_until(at(0.5));
  view.refresh(0);
  CHECK(view.knowledge(0, Generators::positions).points.size() == 2);  // 0.2 s old
  // ... until it is older than 0.25 s, and only at a refresh.
  w.kernel.run_until(at(0.56));
  CHECK(view.knowledge(0, Generators::positions).points.size() == 2);
  view.refresh(0);
  CHECK(view.knowledge(0, Generators::positions).points.size() == 1);
  // Without a limit nothing goes stale.
  World v;
  NetworkedView forever(v.kernel, v.square, network_with_range(1.0), v.state);
  forever.start(SimTime::zero());
  v.kernel.run_until(at(0.3));
  v.state.move(Generators::positions, 1, {2.5, 0.5});
  forever.moved(1);
  v.kernel.run_until(at(5.0));
  forever.refresh(0);
  CHECK(forever.knowledge(0, Generators::positions).points.size() == 2);
}

TEST_CASE("a robot acquires its neighbours first, or goes alone after the timeout", "[view]") {
  World w;
  NetworkConfig c = network_with_range(1.0);
  c.acquire = at(0.2);
  c.acquire_timeout = at(0.7);
  NetworkedView view(w.kernel, w.square, c, w.state);
  view.start(SimTime::zero());
  w.kernel.run_until(at(0.19));
  for (std::uint32_t i = 0; i < 3; ++i)
    CHECK_FALSE(view.ready(i));  // heard or not, the acquisition time has not passed
  w.kernel.run_until(at(0.2));
  CHECK(view.ready(0));
  CHECK(view.ready(1));
  CHECK_FALSE(view.ready(2));  // has heard nobody: waits for a first message
  w.kernel.run_until(at(0.69));
  CHECK_FALSE(view.ready(2));
  w.kernel.run_until(at(0.7));
  CHECK(view.ready(2));  // the deadline: alone, its cell Ω
  CHECK(view.knowledge(2, Generators::positions).points.size() == 1);
  // A robot that hears somebody after the acquisition time is ready from then on.
  World late;
  NetworkConfig d = network_with_range(1.0);
  d.acquire = at(0.2);
  d.acquire_timeout = at(5.0);
  late.state.move(Generators::positions, 1, {3.0, 0.5});  // out of robot 0's range
  NetworkedView lv(late.kernel, late.square, d, late.state);
  lv.start(SimTime::zero());
  late.kernel.run_until(at(0.3));
  CHECK_FALSE(lv.ready(0));
  late.state.move(Generators::positions, 1, {1.0, 0.5});
  lv.moved(1);
  late.kernel.run_until(at(0.4));
  CHECK(lv.ready(0));
}
