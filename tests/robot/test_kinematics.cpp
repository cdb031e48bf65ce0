// Bodies with a heading (robot/turn_then_drive): the time-optimal 1D travel against its
// analytic values, and the turn-then-drive motion: on the segment, within its limits, exact
// on arrival.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "robot/kinematics_registry.hpp"
#include "robot/turn_then_drive.hpp"

using namespace covsim;

TEST_CASE("travel without an acceleration limit moves at the top speed", "[kinematics]") {
  const Travel part = travel(1.0, 0.0, 0.5, INFINITY, 1.0);
  CHECK_FALSE(part.done);
  CHECK(part.covered == Approx(0.5));
  CHECK(part.speed == 0.5);
  const Travel whole = travel(1.0, 0.0, 0.5, INFINITY, 3.0);
  CHECK(whole.done);
  CHECK(whole.covered == 1.0);
  CHECK(whole.time == Approx(2.0));
}

TEST_CASE("travel with an acceleration limit: trapezoid and triangle", "[kinematics]") {
  // Top speed 1, acceleration 1, 3 m: 1 s up (0.5 m), 2 s cruising, 1 s down: 4 s.
  const Travel trapezoid = travel(3.0, 0.0, 1.0, 1.0, 10.0);
  CHECK(trapezoid.done);
  CHECK(trapezoid.time == Approx(4.0));
  CHECK(travel(3.0, 0.0, 1.0, 1.0, 0.5).covered == Approx(0.125));  // a t² / 2
  CHECK(travel(3.0, 0.0, 1.0, 1.0, 2.0).covered == Approx(1.5));    // 0.5 + 1
  const Travel braking = travel(3.0, 0.0, 1.0, 1.0, 3.5);
  CHECK(braking.covered == Approx(3.0 - 0.125));
  CHECK(braking.speed == Approx(0.5));
  // 1 m never reaches the top speed: peak √(a d) = 1... exactly, so 0.5 m: peak √0.5, 2√0.5 s.
  const Travel triangle = travel(0.5, 0.0, 1.0, 1.0, 10.0);
  CHECK(triangle.time == Approx(2.0 * std::sqrt(0.5)));
  // From a speed of 1 with 2 m to go and acceleration 1: cruise 1.5 m, brake 0.5 m: 2.5 s.
  CHECK(travel(2.0, 1.0, 1.0, 1.0, 10.0).time == Approx(2.5));
}

TEST_CASE("random travels never pass the end, never exceed the limits", "[kinematics]") {
  std::uint64_t s = 99;
  auto uniform = [&] {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) / 9007199254740992.0;
  };
  for (int k = 0; k < 2000; ++k) {
    const double length = 2 * uniform(), top = 0.05 + uniform(), a = 0.1 + 3 * uniform();
    const double v0 = std::min(top, std::sqrt(2 * a * length)) * uniform();
    double covered = 0, speed = v0, elapsed = 0;
    for (int step = 0; step < 10000 && covered < length; ++step) {
      const Travel t = travel(length - covered, speed, top, a, 0.05);
      REQUIRE(t.covered >= 0.0);
      REQUIRE(t.speed <= top * (1 + 1e-12));
      // Speeds change no faster than the acceleration over the step.
      REQUIRE(std::fabs(t.speed - speed) <= a * 0.05 * (1 + 1e-9) + 1e-12);
      covered += t.covered;
      speed = t.speed;
      elapsed += t.time;
      if (t.done) break;
    }
    REQUIRE(covered == Approx(length));
    // No slower than the one-go profile by more than rounding.
    CHECK(elapsed == Approx(travel(length, v0, top, a, INFINITY).time).margin(1e-9));
  }
}

TEST_CASE("turn then drive: turning in place costs time, the body stays on the segment",
          "[kinematics]") {
  KinematicLimits l;
  l.speed = 0.1;
  l.turn_rate = 1.0;
  const TurnThenDrive body(l);
  // Facing +x, going to (0, 0.05): a quarter turn (π/2 s at 1 rad/s), then 0.5 s of driving.
  BodyState state;
  Vec2 at{0, 0};
  double t = 0;
  for (; t < 10; t += 0.1) {
    const BodyMotion m = body.move(at, state, {}, {0, 0.05}, 0.1);
    CHECK(m.position.x == Approx(0.0).margin(1e-15));  // on the segment
    CHECK(distance(m.position, at) <= 0.1 * 0.1 + 1e-15);
    CHECK(std::fabs(std::remainder(m.state.heading - state.heading, 2 * std::numbers::pi)) <=
          1.0 * 0.1 + 1e-12);
    at = m.position;
    state = m.state;
    if (m.arrived) break;
  }
  CHECK(at == Vec2{0, 0.05});  // exactly there
  // Turning takes the steps up to π/2 s, driving 0.5 s more: arrival in the 21st step.
  CHECK(t == Approx(2.0));
  CHECK(state.heading == Approx(std::numbers::pi / 2));
}

TEST_CASE("a differential drive turns at twice its wheel speed over its wheel base",
          "[kinematics]") {
  Params p;
  p.set("wheel_base", 0.05);
  const auto body =
      make_kinematics(KinematicsConfig{"differential_drive", p}, KinematicsContext{0.1});
  REQUIRE(body);
  CHECK(body->limits().turn_rate == Approx(4.0));
  CHECK(body->limits().speed == 0.1);
  CHECK_FALSE(make_kinematics(KinematicsConfig{}, KinematicsContext{0.1}));  // single integrator
  CHECK(kinematics_registry().names() ==
        std::vector<std::string>{"single_integrator", "unicycle", "differential_drive"});
}

TEST_CASE("a body driving toward another point stops at once only past its acceleration",
          "[kinematics]") {
  KinematicLimits l;
  l.speed = 0.1;
  l.turn_rate = 1.0;
  l.acceleration = 0.5;
  const TurnThenDrive body(l);
  BodyState moving;
  moving.speed = 0.1;  // facing +x
  const BodyMotion ahead = body.move({0, 0}, moving, {1, 0}, {0.5, 0}, 0.1);
  CHECK_FALSE(ahead.hard_stop);  // straight ahead, room to stop
  const BodyMotion aside = body.move({0, 0}, moving, {1, 0}, {0, 0.5}, 0.1);
  CHECK(aside.hard_stop);
  CHECK(aside.position == Vec2{0, 0});  // it turns from rest
}
