// The robots' colours (analysis/figures/robot_palette): Paul Tol's muted scheme first, then
// darker and lighter rounds of its hues, every colour distinct up to distinct_robot_colours(),
// told apart by eye (CIELAB distances).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "analysis/figures/robot_palette.hpp"

using namespace covsim;

TEST_CASE("the first robots take Paul Tol's muted scheme in its order", "[palette]") {
  const char* muted[] = {"#cc6677", "#332288", "#ddcc77", "#117733", "#88ccee",
                         "#882255", "#44aa99", "#999933", "#aa4499"};
  REQUIRE(robot_hues() == 9);
  for (std::size_t i = 0; i < robot_hues(); ++i)
    CHECK(colour_hex(robot_colour(i)) == muted[i]);
}

namespace {
// CIELAB (D65) of an sRGB colour: distances there are what the eye tells apart (ΔE 2.3 is
// a just noticeable difference).
std::array<double, 3> lab(const Colour& c) {
  const auto linear = [](double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  const double r = linear(c.r), g = linear(c.g), b = linear(c.b);
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}
double delta_e(const Colour& a, const Colour& b) {
  const auto p = lab(a), q = lab(b);
  return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}
// The least ΔE between any two of the first n robots' colours.
double closest(std::size_t n) {
  double out = INFINITY;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j)
      out = std::min(out, delta_e(robot_colour(i), robot_colour(j)));
  return out;
}
}  // namespace

TEST_CASE("forty robots, and more, get colours no other robot has", "[palette]") {
  REQUIRE(distinct_robot_colours() >= 40);
  std::set<std::string> seen;
  for (std::size_t i = 0; i < distinct_robot_colours(); ++i) {
    const Colour a = robot_colour(i);
    INFO("robot " << i << ": " << colour_hex(a));
    CHECK(seen.insert(colour_hex(a)).second);
    // Dark enough to see as a line on white paper.
    CHECK(lab(a)[0] < 90);
  }
  // Several just noticeable differences apart: nine robots by far, forty by five, all by two.
  CHECK(closest(robot_hues()) > 20);
  CHECK(closest(40) > 12);
  CHECK(closest(distinct_robot_colours()) > 6);
  // A round keeps its hue: robot 9 is robot 0 darker, robot 18 lighter.
  const Colour base = robot_colour(0), darker = robot_colour(9), lighter = robot_colour(18);
  CHECK(darker.r < base.r);
  CHECK(lighter.r > base.r);
  CHECK(darker.r / darker.g == Approx(base.r / base.g));
}

TEST_CASE("past the distinct colours, colours repeat from the first", "[palette]") {
  const std::size_t n = distinct_robot_colours();
  CHECK(colour_hex(robot_colour(n)) == colour_hex(robot_colour(0)));
  CHECK(colour_hex(robot_colour(n + 10)) == colour_hex(robot_colour(10)));
}
