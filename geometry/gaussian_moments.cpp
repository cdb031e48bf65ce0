#include "geometry/gaussian_moments.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/cell_integrator.hpp"
#include "geometry/quadrature.hpp"

namespace covsim {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr int kLegendre = 12;  // nodes per piece: pieces of scale one make it exact
constexpr int kLaguerre = 24;
constexpr int kLaguerreFar = 12;  // for a tail known to be below e^{-kMidSpan} of the sum
// A far edge whose exponent falls by at most kMidSpan over it takes one Gauss-Legendre rule of
// kMidLegendre nodes in the exponent (exact for e^{-s} over such a span).
constexpr double kMidSpan = 8.0;
constexpr int kMidLegendre = 16;
constexpr int kDirect = 6;  // nodes per direction on each fan triangle of a small polygon
// Past this many sigma along an edge, e^{-t²/2} < 1e-16: the fan integrand is its atan part.
constexpr double kTail = 8.6;
// A far edge's shadow is taken by Gauss-Legendre up to this many sigma from the foot of the
// perpendicular, by Gauss-Laguerre beyond (where the tail's quadrature converges fast).
constexpr double kLaguerreFrom = 3.0;
// Polygons at least this many sigma from the mean take the shadow (far) form of the mass.
constexpr double kFar = 1.0;
// Polygons whose extent times distance (the span of the exponent over them) is at most this
// are integrated directly: the quadrature is then exact to rounding.
constexpr double kSmallSpan = 0.15;

// Σ over the pieces of [a, b] no longer than `piece` of Gauss-Legendre for f.
template <class F>
double legendre(double a, double b, double piece, const F& f) {
  if (!(b > a)) return 0.0;
  const QuadratureRule& q = gauss_legendre(kLegendre);
  const int n = std::max(1, static_cast<int>(std::ceil((b - a) / piece)));
  const double len = (b - a) / n;
  double sum = 0.0;
  for (int p = 0; p < n; ++p) {
    const double lo = a + p * len;
    double s = 0.0;
    for (int i = 0; i < kLegendre; ++i)
      s += q.weights[static_cast<std::size_t>(i)] *
           f(lo + len * q.nodes[static_cast<std::size_t>(i)]);
    sum += len * s;
  }
  return sum;
}

// An edge in the frame of the perpendicular from the mean: its line at distance h, its ends at
// t = ta < tb along the line from the foot.
struct Edge {
  double h, ta, tb;
};

// The fan triangle (mean, a, b): (1/2π) ∫ (1 - e^{-ρ²/2}) dθ over the angle the edge subtends,
// with ρ² = h² + t² and dθ = h dt / ρ².
double fan_mass(const Edge& e) {
  const double h = e.h;
  if (h == 0.0) return 0.0;
  const auto angle = [h](double lo, double hi) { return std::atan2(hi, h) - std::atan2(lo, h); };
  if (h >= kTail) return angle(e.ta, e.tb) / kTwoPi;
  double sum = 0.0;
  if (e.ta < -kTail) sum += angle(e.ta, std::min(e.tb, -kTail));
  if (e.tb > kTail) sum += angle(std::max(e.ta, kTail), e.tb);
  const double lo = std::max(e.ta, -kTail), hi = std::min(e.tb, kTail);
  sum += legendre(lo, hi, 1.0, [h](double t) {
    const double rho2 = h * h + t * t;
    return -h * std::expm1(-0.5 * rho2) / rho2;
  });
  return sum / kTwoPi;
}

// ∫_{t0}^{te} e^{-(t² - t0²)/2} h / (h² + t²) dt for 0 <= t0 < te: the shadow of [t0, te] with
// the factor e^{-(h² + t0²)/2} taken out, so its relative precision holds at any distance.
double shadow_integral(double h, double t0, double te) {
  const auto f = [h, t0](double t) {
    return h * std::exp(-0.5 * (t - t0) * (t + t0)) / (h * h + t * t);
  };
  // The exponent's fall over [t0, te].
  const double span = 0.5 * (te - t0) * (te + t0);
  if (te - t0 <= 1.0 && span <= 2.0) return legendre(t0, te, 1.0, f);
  if (t0 < kLaguerreFrom) {
    const double mid = std::min(te, kLaguerreFrom);
    double sum = legendre(t0, mid, 1.0, f);
    if (te > mid) sum += std::exp(-0.5 * (mid - t0) * (mid + t0)) * shadow_integral(h, mid, te);
    return sum;
  }
  // Beyond kLaguerreFrom, in s = (t² - t0²) / 2: e^{-s} h / ((h² + t²) t) ds, a smooth factor
  // (its singularities lie at s <= -t0²/2) times e^{-s}.
  const auto g = [h, t0](double s) {
    const double t2 = t0 * t0 + 2.0 * s;
    return h / ((h * h + t2) * std::sqrt(t2));
  };
  if (span <= kMidSpan) {
    const QuadratureRule& q = gauss_legendre(kMidLegendre);
    double sum = 0.0;
    for (int i = 0; i < kMidLegendre; ++i) {
      const double s = span * q.nodes[static_cast<std::size_t>(i)];
      sum += q.weights[static_cast<std::size_t>(i)] * std::exp(-s) * g(s);
    }
    return span * sum;
  }
  // A longer edge: the tail from t0 less the tail from te, each with t = ts + w / ts as
  // e^{-w} e^{-w² / (2 ts²)} h / (h² + t²) dw / ts, a Laguerre weight times a smooth factor.
  // The second is at most e^{-kMidSpan} of the first, so it needs fewer digits.
  const auto tail = [h](double ts, int nodes) {
    const QuadratureRule& q = gauss_laguerre(nodes);
    double sum = 0.0;
    for (int i = 0; i < nodes; ++i) {
      const double w = q.nodes[static_cast<std::size_t>(i)] / ts, t = ts + w;
      sum += q.weights[static_cast<std::size_t>(i)] * std::exp(-0.5 * w * w) * h / (h * h + t * t);
    }
    return sum / ts;
  };
  double sum = tail(t0, kLaguerre);
  if (span < 40.0) sum -= std::exp(-span) * tail(te, kLaguerreFar);
  return sum;
}

// The shadow of an edge: (1/2π) ∫ e^{-ρ²/2} dθ over the angle it subtends, the mass of the part
// of that wedge beyond the edge.
double shadow_mass(const Edge& e) {
  const double h = e.h;
  if (e.ta >= 0.0)
    return std::exp(-0.5 * (h * h + e.ta * e.ta)) / kTwoPi * shadow_integral(h, e.ta, e.tb);
  if (e.tb <= 0.0)
    return std::exp(-0.5 * (h * h + e.tb * e.tb)) / kTwoPi * shadow_integral(h, -e.tb, -e.ta);
  return std::exp(-0.5 * h * h) / kTwoPi *
         (shadow_integral(h, 0.0, e.tb) + shadow_integral(h, 0.0, -e.ta));
}

// ∫ φ ds along the edge: e^{-h²/2} / (2π) ∫ e^{-t²/2} dt, by erf or by erfc in the tails.
double line_integral(const Edge& e) {
  constexpr double r = M_SQRT1_2;
  double d;
  if (e.ta > 0.0) {
    d = std::erfc(e.ta * r) - std::erfc(e.tb * r);
  } else if (e.tb < 0.0) {
    d = std::erfc(-e.tb * r) - std::erfc(-e.ta * r);
  } else {
    d = std::erf(e.tb * r) - std::erf(e.ta * r);
  }
  return std::exp(-0.5 * e.h * e.h) * std::sqrt(M_PI / 2.0) * d / kTwoPi;
}

// Moments of the standard normal density about the origin over a small polygon (z: its
// vertices in units of sigma), on its fan of triangles from the first vertex.
Moments direct_moments(const std::vector<Vec2>& z) {
  const QuadratureRule& q = gauss_legendre(kDirect);
  Moments out;
  for (std::size_t k = 1; k + 1 < z.size(); ++k) {
    const Vec2 a = z[0], b = z[k], c = z[k + 1];
    const double two_area = std::fabs(cross(b - a, c - a));
    for (int i = 0; i < kDirect; ++i) {
      const double u = q.nodes[static_cast<std::size_t>(i)];
      const Vec2 p = a + u * (b - a), s = u * (c - b);
      const double wu = q.weights[static_cast<std::size_t>(i)] * u * two_area / kTwoPi;
      for (int j = 0; j < kDirect; ++j) {
        const Vec2 x = p + q.nodes[static_cast<std::size_t>(j)] * s;
        const double w = wu * q.weights[static_cast<std::size_t>(j)] * std::exp(-0.5 * norm2(x));
        out.mass += w;
        out.first += w * x;
        out.second += w * norm2(x);
      }
    }
  }
  return out;
}

// Moments of the standard normal density about the origin over a convex polygon.
Moments standard_moments(const std::vector<Vec2>& z) {
  const std::size_t n = z.size();
  bool inside = true;
  double near2 = INFINITY, far2 = 0.0;
  Box box;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = z[i], d = z[(i + 1) % n] - a;
    if (cross(d, -a) < 0.0) inside = false;
    const double len2 = norm2(d);
    const double t = len2 > 0.0 ? std::clamp(-dot(a, d) / len2, 0.0, 1.0) : 0.0;
    near2 = std::min(near2, norm2(a + t * d));
    far2 = std::max(far2, norm2(a));
    box.add(a);
  }
  const double extent = std::sqrt(norm2(box.size()));
  if (extent * (std::sqrt(far2) + extent) <= kSmallSpan) return direct_moments(z);
  const bool far = !inside && near2 >= kFar * kFar;
  Moments m;
  double edge_first_x = 0.0, edge_first_y = 0.0, edge_second = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = z[i], d = z[(i + 1) % n] - a;
    const double len = std::sqrt(norm2(d));
    if (!(len > 0.0)) continue;
    const Vec2 u = d / len;
    // c > 0: the mean lies on the inner side of this edge (counter-clockwise polygon).
    const double c = cross(a, u);
    const Edge e{std::fabs(c), dot(a, u), dot(a, u) + len};
    const double side = c >= 0.0 ? 1.0 : -1.0;
    // Inside: every fan triangle counts positively, so no term cancels another. Outside and
    // far: the polygon is the near edges' shadows less the far edges'.
    m.mass += far ? -side * shadow_mass(e) : side * fan_mass(e);
    // ∫ zφ = -∮ φ n ds and ∫ |z|²φ = 2∫φ - ∮ (z·n) φ ds, with n the outward normal (u.y, -u.x)
    // and z·n = c along the edge.
    const double line = line_integral(e);
    edge_first_x -= u.y * line;
    edge_first_y += u.x * line;
    edge_second -= c * line;
  }
  m.first = {edge_first_x, edge_first_y};
  m.second = edge_second + 2.0 * m.mass;
  return m;
}

}  // namespace

Moments gaussian_moments(const ConvexPolygon& polygon, Vec2 mean, double sigma, Vec2 r) {
  if (polygon.size() < 3) return {};
  std::vector<Vec2> z(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i)
    z[i] = (polygon[i] - mean) / sigma;
  const Moments s = standard_moments(z);
  // Back to metres about the mean (the standard density's 1/2π and the area element σ²),
  // then about r.
  const double s2 = sigma * sigma, mass_scale = kTwoPi * s2;
  const Moments about_mean{mass_scale * s.mass, (mass_scale * sigma) * s.first,
                           (mass_scale * s2) * s.second};
  return shift_moments(about_mean, mean, r);
}

}  // namespace covsim
