#pragma once
// Gauss-Legendre quadrature on triangles by the collapsed-square (Duffy) map: with m
// points per direction it integrates polynomials of total degree up to 2m - 2 exactly.
#include <functional>
#include <vector>

#include "geometry/convex_polygon.hpp"

namespace covsim {

struct QuadratureRule {
  std::vector<double> nodes;    // on [0, 1]
  std::vector<double> weights;  // summing to 1
};
// m-point Gauss-Legendre on [0, 1], computed by Newton's method on P_m (cached for m <= 32).
const QuadratureRule& gauss_legendre(int m);
// m-point Gauss-Laguerre: ∫_0^∞ e^{-x} f(x) dx ≈ Σ w_i f(x_i), exact for polynomials of degree
// up to 2m - 1; Newton's method on L_m in long double (cached for m <= 32).
const QuadratureRule& gauss_laguerre(int m);

// Moments of f over the triangle (a, b, c) relative to r, with m points per direction.
template <class F>
Moments triangle_moments(Vec2 a, Vec2 b, Vec2 c, Vec2 r, const F& f, int m) {
  const QuadratureRule& q = gauss_legendre(m);
  const double two_area = std::fabs(cross(b - a, c - a));
  Moments out;
  for (int i = 0; i < m; ++i) {
    const double u = q.nodes[static_cast<std::size_t>(i)];
    const Vec2 p = a + u * (b - a), s = u * (c - b);
    const double wu = q.weights[static_cast<std::size_t>(i)] * u * two_area;
    for (int j = 0; j < m; ++j) {
      const Vec2 x = p + q.nodes[static_cast<std::size_t>(j)] * s;
      const double w = wu * q.weights[static_cast<std::size_t>(j)] * f(x);
      const Vec2 d = x - r;
      out.mass += w;
      out.first += w * d;
      out.second += w * norm2(d);
    }
  }
  return out;
}

}  // namespace covsim
