// Localization (robots.localization): a tracking system's estimates differ from the truth as
// configured (the fixes' noise, the lag of their latency), odometry drifts as the square root
// of the distance travelled, and the registry builds what a scenario names.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <numbers>

#include "robot/dead_reckoning.hpp"
#include "robot/event_classes.hpp"
#include "robot/localization_registry.hpp"

using namespace covsim;

namespace {

// Robots whose real positions the test moves, each motion reported to the localization.
struct World {
  Kernel kernel;
  std::vector<Vec2> real;
  std::unique_ptr<Localization> loc;
  World(std::uint64_t seed, std::size_t n, const std::string& type, Params params)
      : kernel(seed), real(n, Vec2{0.0, 0.0}) {
    loc = make_localization(
        LocalizationConfig{type, std::move(params)},
        LocalizationContext{kernel, real, [this](std::uint32_t i) { return real[i]; }});
  }
  void move(std::uint32_t i, Vec2 d) {
    real[i] = real[i] + d;
    loc->moved(i, d);
  }
};

Params params(std::initializer_list<std::pair<const char*, ParamValue>> values) {
  Params p;
  for (const auto& [name, v] : values)
    p.set(name, v);
  return p;
}

struct AxisStats {
  double mean = 0.0, sd = 0.0, mean_norm = 0.0;
};

AxisStats errors(World& w) {
  // Both axes pooled.
  AxisStats s;
  std::vector<double> e;
  for (std::uint32_t i = 0; i < w.real.size(); ++i) {
    const Vec2 d = w.loc->estimate(i) - w.real[i];
    e.push_back(d.x);
    e.push_back(d.y);
    s.mean_norm += norm(d) / static_cast<double>(w.real.size());
  }
  for (double x : e)
    s.mean += x / static_cast<double>(e.size());
  for (double x : e)
    s.sd += (x - s.mean) * (x - s.mean) / static_cast<double>(e.size() - 1);
  s.sd = std::sqrt(s.sd);
  return s;
}

// The estimate's lag behind robot 0 driven along x at `speed`, a motion step every `dt`
// with the estimate read after it (as loop 2 does), the frames after the motion at their
// instants, for 3 s: the largest error, and the largest once `latency` and a frame have
// passed. `each` is called after every step.
struct Lag {
  double worst = 0.0, settled = 0.0;
};
Lag drive(
    World& w, double speed, double dt, double latency, const std::function<void()>& each = [] {}) {
  Lag lag;
  const EventKind step = w.kernel.add_kind("step", [&](Kernel& k, const Event&) {
    w.move(0, {speed * dt, 0.0});
    const double error = distance(w.loc->estimate(0), w.real[0]);
    lag.worst = std::max(lag.worst, error);
    if (k.now() > SimTime::from_seconds(latency + 0.1)) lag.settled = std::max(lag.settled, error);
    each();
  });
  w.kernel.schedule_periodic(Period::from_seconds(dt), SimTime::from_seconds(dt), step, 0,
                             event_class::loop2);
  w.loc->start(SimTime::zero());
  w.kernel.run_until(SimTime::from_seconds(3.0));
  return lag;
}

}  // namespace

TEST_CASE("exact localization builds nothing: the controller uses the positions",
          "[localization]") {
  Kernel kernel(1);
  const std::vector<Vec2> starts{{0.0, 0.0}};
  CHECK(make_localization(
            LocalizationConfig{},
            LocalizationContext{kernel, starts, [](std::uint32_t) { return Vec2{}; }}) == nullptr);
  CHECK_THROWS_WITH(
      make_localization(LocalizationConfig{"gps", {}},
                        LocalizationContext{kernel, starts, [](std::uint32_t) { return Vec2{}; }}),
      Catch::Matchers::Contains("tracking"));
}

TEST_CASE("a tracking fix is the position with Gaussian noise of the configured deviation",
          "[localization]") {
  const double sigma = 0.01;
  World w(3, 4000, "tracking", params({{"rate", 10.0}, {"noise", sigma}}));
  for (std::uint32_t i = 0; i < w.real.size(); ++i)
    w.real[i] = {0.001 * i, 0.5};
  // Before the first frame the robots know their starts exactly.
  CHECK(w.loc->estimate(7) == Vec2{0.0, 0.0});
  w.loc->start(SimTime::zero());
  w.kernel.run_until(SimTime::from_seconds(0.05));  // the frame at 0 s, delivered at once
  const AxisStats s = errors(w);
  CHECK(w.loc->fixes() == 4000);
  // 8000 draws: the mean within 4 of its standard errors, the deviation within 5%.
  CHECK(std::fabs(s.mean) < 4.0 * sigma / std::sqrt(8000.0));
  CHECK(s.sd == Approx(sigma).epsilon(0.05));
  CHECK(s.mean_norm == Approx(sigma * std::sqrt(std::numbers::pi / 2.0)).epsilon(0.05));
  // The next frame draws afresh: independent errors.
  const Vec2 first = w.loc->estimate(0) - w.real[0];
  w.kernel.run_until(SimTime::from_seconds(0.15));
  const AxisStats again = errors(w);
  CHECK_FALSE(w.loc->estimate(0) - w.real[0] == first);
  CHECK(w.loc->fixes() == 8000);
  CHECK(again.sd == Approx(sigma).epsilon(0.05));
}

TEST_CASE("a late fix leaves a moving robot's estimate behind by its speed times the latency",
          "[localization]") {
  const double speed = 0.1, latency = 0.2, dt = 0.01;
  const bool compensated = GENERATE(false, true);
  World w(
      5, 1, "tracking",
      params({{"rate", 10.0}, {"latency", latency}, {"noise", 0.0}, {"compensated", compensated}}));
  const auto [worst, settled] = drive(w, speed, dt, latency);
  if (compensated) {
    // The odometry's motion since the capture added: nothing lost but rounding.
    CHECK(worst < 1e-12);
  } else {
    // Each fix is taken as the position when it arrives, latency after its capture: the robot
    // has moved speed * latency since; odometry keeps that lag until the next fix.
    CHECK(settled == Approx(speed * latency).epsilon(1e-9));
    CHECK(worst <= speed * latency * (1 + 1e-9));
  }
  CHECK(w.loc->fixes() == 29);  // the frames of 0 ... 2.8 s, delivered by 3 s
}

TEST_CASE("odometry drifts as the square root of the distance travelled", "[localization]") {
  const double drift = 0.02;
  for (const double metres : {0.25, 1.0}) {
    World w(9, 3000, "odometry", params({{"drift", drift}}));
    // Each robot drives `metres` in 1 cm steps, turning left every 10 cm.
    for (std::uint32_t i = 0; i < w.real.size(); ++i) {
      Vec2 dir{1.0, 0.0};
      for (int k = 0; k < static_cast<int>(std::lround(metres / 0.01)); ++k) {
        if (k % 10 == 9) dir = Vec2{-dir.y, dir.x};
        w.move(i, 0.01 * dir);
      }
    }
    const AxisStats s = errors(w);
    INFO("distance " << metres << " m");
    CHECK(std::fabs(s.mean) < 4.0 * drift * std::sqrt(metres) / std::sqrt(6000.0));
    CHECK(s.sd == Approx(drift * std::sqrt(metres)).epsilon(0.05));
    CHECK(w.loc->fixes() == 0);
    // A robot that does not move does not drift.
    const Vec2 before = w.loc->odometry(0);
    w.move(0, {0.0, 0.0});
    CHECK(w.loc->odometry(0) == before);
  }
}

TEST_CASE("a tracking system corrects the odometry's drift at each fix", "[localization]") {
  World w(13, 500, "tracking",
          params({{"rate", 2.0}, {"noise", 0.001}, {"drift", 0.05}, {"latency", 0.0}}));
  w.loc->start(SimTime::zero());
  w.kernel.run_until(SimTime::from_seconds(0.1));  // the frame at 0 s sees the starts
  CHECK(errors(w).sd == Approx(0.001).epsilon(0.1));
  // Two metres each in 1 cm steps before the next frame: drift 0.05 √2 ≈ 7 cm.
  for (std::uint32_t i = 0; i < w.real.size(); ++i)
    for (int k = 0; k < 200; ++k)
      w.move(i, {0.01, 0.0});
  const AxisStats drifted = errors(w);
  CHECK(drifted.sd > 0.05);
  w.kernel.run_until(SimTime::from_seconds(0.6));  // the frame at 0.5 s saw the positions
  const AxisStats fixed = errors(w);
  CHECK(fixed.sd == Approx(0.001).epsilon(0.1));
  // What the planner's margins and the controller's reach allow for: the odometry's drift
  // over a step, and with the fixes' noise on top.
  CHECK(w.loc->odometry_jitter(0.01) == Approx(0.005));
  CHECK(w.loc->estimate_jitter(0.01) == Approx(std::sqrt(2e-6 + 0.05 * 0.05 * 0.01)));
}

TEST_CASE("the same seed gives the same estimates", "[localization]") {
  const auto sample = [](std::uint64_t seed) {
    World w(seed, 3, "tracking", params({{"noise", 0.003}, {"drift", 0.01}}));
    w.loc->start(SimTime::zero());
    for (int k = 0; k < 50; ++k)
      w.move(k % 3, {0.01, 0.002});
    w.kernel.run_until(SimTime::from_seconds(0.35));
    return std::vector<Vec2>{w.loc->estimate(0), w.loc->estimate(1), w.loc->estimate(2)};
  };
  CHECK(sample(21) == sample(21));
  CHECK_FALSE(sample(21) == sample(22));
}

TEST_CASE("a remote-controlled robot's estimate is the last fix; a frame may miss its marker",
          "[localization]") {
  const double speed = 0.1, latency = 0.2, dt = 0.01;
  World w(5, 2, "tracking",
          params({{"rate", 10.0}, {"latency", latency}, {"noise", 0.0}, {"remote", true}}));
  // Robot 0 moves along x; the estimate stays at the last fix between fixes (no odometry),
  // which is where the robot was at the capture, latency before it arrived.
  const auto [worst, settled] = drive(w, speed, dt, latency, [&] {
    CHECK(w.loc->odometry(0) == w.loc->estimate(0));  // the planner works from the fix
  });
  // Up to a frame period of motion more than the latency's.
  CHECK(settled > speed * latency);
  CHECK(worst <= speed * (latency + 0.1) * (1 + 1e-9) + 1e-12);
  CHECK(w.loc->estimate_sigma(speed).value() == Approx(speed * (latency + 0.1)));
  CHECK(w.loc->fixes() == 29);  // robot 0's: a fix counts when it is applied

  // Markers lost in about a fifth of the frames: fewer fixes, the same for the same seed.
  const auto fixes = [](double loss, std::uint64_t seed) {
    World l(seed, 4, "tracking", params({{"rate", 10.0}, {"loss", loss}}));
    l.loc->start(SimTime::zero());
    l.kernel.run_until(SimTime::from_seconds(10.0));
    for (std::uint32_t i = 0; i < 4; ++i)
      l.loc->estimate(i);
    return l.loc->fixes();
  };
  CHECK(fixes(0.0, 3) == 4 * 101);
  const std::uint64_t lossy = fixes(0.2, 3);
  CHECK(lossy == fixes(0.2, 3));
  CHECK(lossy > 4 * 101 * 0.7);
  CHECK(lossy < 4 * 101 * 0.9);
  CHECK(fixes(1.0, 3) == 0);
}
