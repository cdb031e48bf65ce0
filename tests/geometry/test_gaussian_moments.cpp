// Exact Gaussian moments over convex polygons (geometry/gaussian_moments.hpp) against closed
// forms (the plane, half-planes, rectangles as products of erf) and against an independent
// long double reference (strips in y, each a difference of normal distribution functions).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/random_stream.hpp"
#include "geometry/gaussian_mixture_density.hpp"
#include "geometry/gaussian_moments.hpp"
#include "geometry/quadrature.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;

namespace {

using LD = long double;
constexpr LD kPi = 3.14159265358979323846264338327950288L;

LD normal_cdf(LD x) {
  return 0.5L * std::erfc(-x / std::sqrt(2.0L));
}
LD normal_pdf(LD x) {
  return std::exp(-0.5L * x * x) / std::sqrt(2.0L * kPi);
}
// P(a < X < b) for a standard normal X, in relative precision in either tail.
LD normal_mass(LD a, LD b) {
  return a > 0 ? normal_cdf(-a) - normal_cdf(-b) : normal_cdf(b) - normal_cdf(a);
}

// Moments about the origin of the standard normal density (in units of sigma).
struct Reference {
  LD mass = 0, fx = 0, fy = 0, second = 0;
};

// The rectangle [x0, x1] x [y0, y1]: products of one-dimensional moments.
Reference rectangle(LD x0, LD x1, LD y0, LD y1) {
  const LD px = normal_mass(x0, x1), py = normal_mass(y0, y1);
  const LD mx = normal_pdf(x0) - normal_pdf(x1), my = normal_pdf(y0) - normal_pdf(y1);
  const LD sx = px + x0 * normal_pdf(x0) - x1 * normal_pdf(x1);
  const LD sy = py + y0 * normal_pdf(y0) - y1 * normal_pdf(y1);
  return {px * py, mx * py, my * px, sx * py + sy * px};
}

// A convex polygon, by Gauss-Legendre in y over strips [x_left(y), x_right(y)], each strip's
// moments in closed form in x; in long double, pieces short against the density's scale.
Reference strips(const std::vector<Vec2>& poly) {
  const QuadratureRule& q = gauss_legendre(32);
  std::vector<LD> ys;
  for (Vec2 p : poly)
    ys.push_back(p.y);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  const auto span = [&](LD y, LD& lo, LD& hi) {
    lo = INFINITY;
    hi = -INFINITY;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      if (a.y == b.y || y < std::min(a.y, b.y) || y > std::max(a.y, b.y)) continue;
      const LD x = a.x + (y - a.y) * (LD(b.x) - a.x) / (LD(b.y) - a.y);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  };
  Reference out;
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
    const LD far = std::max(std::fabs(ys[k]), std::fabs(ys[k + 1]));
    const int n = std::max(1, static_cast<int>(std::ceil((ys[k + 1] - ys[k]) * (1 + far) / 0.05L)));
    const LD len = (ys[k + 1] - ys[k]) / n;
    for (int p = 0; p < n; ++p) {
      for (std::size_t i = 0; i < q.nodes.size(); ++i) {
        const LD y = ys[k] + len * (p + LD(q.nodes[i]));
        LD lo, hi;
        span(y, lo, hi);
        if (!(hi > lo)) continue;
        const LD w = len * q.weights[i] * normal_pdf(y), m = normal_mass(lo, hi);
        out.mass += w * m;
        out.fx += w * (normal_pdf(lo) - normal_pdf(hi));
        out.fy += w * y * m;
        out.second += w * (y * y * m + m + lo * normal_pdf(lo) - hi * normal_pdf(hi));
      }
    }
  }
  return out;
}

// The worst errors of gaussian_moments (σ = 1, mean 0, about the origin) against a
// reference, in units of the problem's conditioning: a polygon r sigma away and w thin
// changes its mass by about (1 + r / w) ε relative when its vertices move by one rounding,
// so no method can do better. Mass and second moment relative, the centroid as a distance
// relative to its own distance from the mean plus the polygon's extent.
struct Errors {
  double mass = 0, centroid = 0, second = 0;
  void add(const std::vector<Vec2>& poly, const Reference& ref) {
    const Moments m = gaussian_moments(poly, {0, 0}, 1.0, {0, 0});
    const double scale = 1.0 / (2.0 * M_PI);  // the standard density's factor
    Box box;
    double far = 0;
    for (Vec2 p : poly) {
      box.add(p);
      far = std::max(far, norm(p));
    }
    const double extent = norm(box.size()), width = 2 * std::fabs(signed_area(poly)) / extent;
    const double cond = std::numeric_limits<double>::epsilon() * (1 + far / width);
    const Vec2 c = m.first / m.mass;
    const Vec2 cref{static_cast<double>(ref.fx / ref.mass), static_cast<double>(ref.fy / ref.mass)};
    mass = std::max(mass, std::fabs(m.mass * scale - double(ref.mass)) / double(ref.mass) / cond);
    centroid = std::max(centroid, distance(c, cref) / (norm(cref) + extent) / cond);
    second = std::max(second,
                      std::fabs(m.second * scale - double(ref.second)) / double(ref.second) / cond);
  }
};

}  // namespace

TEST_CASE("Gauss-Laguerre integrates x^k e^-x to k! exactly", "[quadrature]") {
  for (int m : {4, 12, 24}) {
    const QuadratureRule& q = gauss_laguerre(m);
    REQUIRE(q.nodes.size() == static_cast<std::size_t>(m));
    double factorial = 1.0;
    for (int k = 0; k < std::min(2 * m, 30); ++k) {
      if (k > 0) factorial *= k;
      double s = 0.0;
      for (int i = 0; i < m; ++i)
        s += q.weights[i] * std::pow(q.nodes[i], k);
      INFO("m = " << m << ", k = " << k);
      CHECK(s == Approx(factorial).epsilon(1e-13));
    }
  }
}

TEST_CASE("the Gaussian over the plane, a half-plane and a quadrant", "[gaussian]") {
  const double sigma = 0.7, big = 60 * sigma;
  const Vec2 mu{3.0, -2.0};
  const double full = 2 * M_PI * sigma * sigma;
  // The plane (a square 60 sigma wide): mass 2πσ², centroid the mean, ∫|x - μ|² = 4πσ⁴.
  const Moments plane =
      gaussian_moments(square(mu.x - big, mu.y - big, mu.x + big, mu.y + big), mu, sigma, mu);
  CHECK(plane.mass == Approx(full).epsilon(1e-15));
  CHECK(std::fabs(plane.first.x) < 1e-15 * full * sigma);
  CHECK(std::fabs(plane.first.y) < 1e-15 * full * sigma);
  CHECK(plane.second == Approx(2 * full * sigma * sigma).epsilon(1e-15));
  // The half-plane x > μx: half the mass, ∫(x - μx) = σ³ √(2π), and the same about any point.
  const Moments half =
      gaussian_moments(square(mu.x, mu.y - big, mu.x + big, mu.y + big), mu, sigma, mu);
  CHECK(half.mass == Approx(full / 2).epsilon(1e-15));
  CHECK(half.first.x == Approx(sigma * sigma * sigma * std::sqrt(2 * M_PI)).epsilon(1e-15));
  CHECK(std::fabs(half.first.y) < 1e-15 * full * sigma);
  CHECK(half.second == Approx(full * sigma * sigma).epsilon(1e-15));
  // A quadrant seen from a point elsewhere: the parallel-axis shift of the same moments.
  const Vec2 r{10.0, 4.0};
  const Moments quad = gaussian_moments(square(mu.x, mu.y, mu.x + big, mu.y + big), mu, sigma, r);
  const double q0 = full / 4, q1 = sigma * sigma * sigma * std::sqrt(2 * M_PI) / 2;
  CHECK(quad.mass == Approx(q0).epsilon(1e-15));
  CHECK(quad.first.x == Approx(q1 + (mu.x - r.x) * q0).epsilon(1e-14));
  CHECK(quad.first.y == Approx(q1 + (mu.y - r.y) * q0).epsilon(1e-14));
  // A square far out in the tail (e^-700 of the peak) keeps its relative precision.
  const Reference tail = rectangle(37, 38, -2, -1);
  const Moments t = gaussian_moments(square(37, -2, 38, -1), {0, 0}, 1.0, {0, 0});
  CHECK(t.mass / (2 * M_PI) == Approx(double(tail.mass)).epsilon(1e-13));
  CHECK(t.first.x / t.mass == Approx(double(tail.fx / tail.mass)).epsilon(1e-13));
}

TEST_CASE("rectangles anywhere, of any size, match products of erf", "[gaussian]") {
  RandomStream rng(2026, 0, "rectangles");
  Errors e;
  for (int k = 0; k < 4000; ++k) {
    const double x0 = rng.uniform(-12, 12), y0 = rng.uniform(-12, 12);
    const double w = std::pow(10.0, rng.uniform(-3, 1)), h = std::pow(10.0, rng.uniform(-3, 1));
    const Reference ref = rectangle(x0, x0 + w, y0, y0 + h);
    if (!(ref.mass > 1e-300L)) continue;
    e.add(square(x0, y0, x0 + w, y0 + h), ref);
  }
  INFO("worst errors in units of the conditioning: mass " << e.mass << ", centroid " << e.centroid
                                                          << ", second " << e.second);
  CHECK(e.mass < 64);
  CHECK(e.centroid < 64);
  CHECK(e.second < 64);
}

TEST_CASE("convex polygons at any angle match the strip reference", "[gaussian]") {
  RandomStream rng(2026, 1, "polygons");
  Errors e;
  for (int k = 0; k < 600; ++k) {
    // Vertices on an ellipse (aspect at least 1/10, 1e-2 to 5 sigma across) at random
    // angles, rotated, up to 11 sigma from the mean: every kind of edge and every form.
    const Vec2 c{rng.uniform(-8, 8), rng.uniform(-8, 8)};
    const double size = std::pow(10.0, rng.uniform(-2, 0.7)), aspect = rng.uniform(0.1, 1.0);
    const double turn = rng.uniform(0, 2 * M_PI);
    const int n = 3 + static_cast<int>(rng.below(6));
    std::vector<double> angles;
    for (int i = 0; i < n; ++i)
      angles.push_back(rng.uniform(0, 2 * M_PI));
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> poly;
    for (double a : angles) {
      const Vec2 p{size * std::cos(a), size * aspect * std::sin(a)};
      poly.push_back(c + Vec2{std::cos(turn) * p.x - std::sin(turn) * p.y,
                              std::sin(turn) * p.x + std::cos(turn) * p.y});
    }
    // Compact ones: the strip reference loses digits on slivers (a nearly flat edge's x at a
    // given y), which the rectangles cover.
    if (std::fabs(signed_area(poly)) < 0.1 * size * size * aspect) continue;
    const Reference ref = strips(poly);
    if (!(ref.mass > 1e-300L)) continue;
    e.add(poly, ref);
  }
  INFO("worst errors in units of the conditioning: mass " << e.mass << ", centroid " << e.centroid
                                                          << ", second " << e.second);
  CHECK(e.mass < 64);
  CHECK(e.centroid < 64);
  CHECK(e.second < 64);
}

TEST_CASE("a mixture leaves out only bumps that cannot change its moments", "[gaussian]") {
  // Bumps near and far from a cell, with and without a floor: the mixture's moments are the
  // sum of every bump's, to the last few bits, though the far ones are skipped.
  std::vector<GaussianComponent> bumps{
      {{0.5, 0.5}, 0.3, 2.0}, {{30, 30}, 0.4, 5.0}, {{3, -1}, 1.0, 1.0}, {{-50, 10}, 2.0, 9.0}};
  const ConvexPolygon cell{{0, 0}, {1, 0}, {1.2, 0.8}, {0.2, 1.1}};
  const Vec2 r{0.4, 0.6};
  for (double floor : {0.0, 0.01}) {
    const GaussianMixtureDensity mixture(bumps, floor);
    Moments sum = polygon_moments(cell, r).scaled(floor);
    for (const GaussianComponent& b : bumps)
      sum += gaussian_moments(cell, b.mean, b.sigma, r).scaled(b.weight);
    const Moments m = mixture.integrate(cell, r);
    CHECK(m.mass == Approx(sum.mass).epsilon(1e-15));
    CHECK(m.first.x == Approx(sum.first.x).epsilon(1e-14));
    CHECK(m.first.y == Approx(sum.first.y).epsilon(1e-14));
    CHECK(m.second == Approx(sum.second).epsilon(1e-15));
  }
  // Far from every bump and with no floor, a cell still gets its (tiny) mass and centroid.
  const GaussianMixtureDensity lonely({{{0, 0}, 1.0, 1.0}}, 0.0);
  const Moments m = lonely.integrate(square(20, 0, 21, 1), {20.5, 0.5});
  const Reference ref = rectangle(20, 21, 0, 1);
  CHECK(m.mass / (2 * M_PI) == Approx(double(ref.mass)).epsilon(1e-13));
  CHECK(20.5 + m.first.x / m.mass == Approx(double(ref.fx / ref.mass)).epsilon(1e-13));
}
