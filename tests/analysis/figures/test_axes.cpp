#include <catch2/catch.hpp>

#include <cmath>

#include "analysis/figures/axes.hpp"

using namespace covsim;

TEST_CASE("a log x axis puts each decade the same number of pixels apart", "[axes]") {
  const Axes a = chart_axes(Box{{10, 1}, {1000, 5}}, {80, 40}, {660, 364}, false, true);
  CHECK(a.log_x);
  CHECK(a.data.lo.x == Approx(10));
  CHECK(a.data.hi.x == Approx(1000));
  const double x10 = a.to_px({10, 2}).x, x100 = a.to_px({100, 2}).x, x1000 = a.to_px({1000, 2}).x;
  CHECK(x10 == Approx(80));
  CHECK(x1000 == Approx(660));
  CHECK(x100 - x10 == Approx(x1000 - x100));
  // y stays linear: its range is rounded to ticks, 2 lies where it falls.
  CHECK(a.to_px({10, 2}).y == Approx(364 - (2 - a.data.lo.y) / (a.data.hi.y - a.data.lo.y) * 324));
}

TEST_CASE("a log x axis widens its range to whole decades", "[axes]") {
  const Axes a = chart_axes(Box{{150, 0.5}, {2500, 40}}, {0, 0}, {100, 100}, true, true);
  CHECK(a.data.lo.x == Approx(100));
  CHECK(a.data.hi.x == Approx(10000));
  CHECK(a.data.lo.y == Approx(0.1));
  CHECK(a.data.hi.y == Approx(100));
  // No positive data: one decade rather than a log of zero.
  const Axes empty = chart_axes(Box{{0, 1}, {0, 2}}, {0, 0}, {100, 100}, false, true);
  CHECK(empty.data.lo.x > 0);
  CHECK(empty.data.hi.x == Approx(10 * empty.data.lo.x));
  CHECK(std::isfinite(empty.to_px({empty.data.lo.x, 1}).x));
}

TEST_CASE("axes stay linear in x unless asked", "[axes]") {
  const Axes a = chart_axes(Box{{10, 1}, {1000, 5}}, {0, 0}, {100, 100});
  CHECK_FALSE(a.log_x);
  CHECK(a.to_px({500, 1}).x == Approx(100 * (500 - a.data.lo.x) / (a.data.hi.x - a.data.lo.x)));
}
