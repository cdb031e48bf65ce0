#include "geometry/quadrature.hpp"

#include <array>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace covsim {

namespace {
QuadratureRule compute(int m) {
  QuadratureRule q;
  for (int i = 1; i <= m; ++i) {
    // Newton on the Legendre polynomial P_m from the Chebyshev-like initial guess.
    double x = std::cos(M_PI * (i - 0.25) / (m + 0.5));
    double dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= m; ++k) {
        const double pk = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      const double pm = m == 0 ? 1.0 : p1;
      const double pm1 = p0;
      dp = m * (x * pm - pm1) / (x * x - 1.0);
      const double dx = pm / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    q.nodes.push_back(0.5 * (1.0 - x));
    q.weights.push_back(1.0 / ((1.0 - x * x) * dp * dp));  // 2 / (...) on [-1, 1], halved
  }
  return q;
}

// L_m(x) and L_{m-1}(x) by the three-term recurrence.
void laguerre(int m, long double x, long double& lm, long double& lm1) {
  long double p0 = 1.0L, p1 = 1.0L - x;
  if (m == 1) {
    lm = p1;
    lm1 = p0;
    return;
  }
  for (int k = 2; k <= m; ++k) {
    const long double pk = ((2.0L * k - 1.0L - x) * p1 - (k - 1.0L) * p0) / k;
    p0 = p1;
    p1 = pk;
  }
  lm = p1;
  lm1 = p0;
}

QuadratureRule compute_laguerre(int m) {
  QuadratureRule q;
  long double x = 0.0L;
  for (int i = 0; i < m; ++i) {
    // Initial guesses that Newton's method refines to each root in turn (the roots of L_m
    // spread out roughly geometrically).
    if (i == 0) {
      x = 3.0L / (1.0L + 2.4L * m);
    } else if (i == 1) {
      x += 15.0L / (1.0L + 2.5L * m);
    } else {
      const long double a = i - 1;
      x += (1.0L + 2.55L * a) / (1.9L * a) * (x - static_cast<long double>(q.nodes[i - 2]));
    }
    long double lm = 0.0L, lm1 = 0.0L;
    for (int it = 0; it < 200; ++it) {
      laguerre(m, x, lm, lm1);
      const long double dl = m * (lm - lm1) / x;  // x L_m' = m (L_m - L_{m-1})
      const long double dx = lm / dl;
      x -= dx;
      if (std::fabs(dx) <= 1e-19L * x) break;
    }
    laguerre(m, x, lm, lm1);
    // w = x / ((m + 1)² L_{m+1}(x)²), and at a root L_{m+1} = -m L_{m-1} / (m + 1).
    q.nodes.push_back(static_cast<double>(x));
    q.weights.push_back(static_cast<double>(x / (static_cast<long double>(m) * m * lm1 * lm1)));
  }
  return q;
}
}  // namespace

const QuadratureRule& gauss_laguerre(int m) {
  static std::array<QuadratureRule, 33> rules;
  static std::array<std::once_flag, 33> once;
  if (m < 1 || m > 32) throw std::out_of_range("gauss_laguerre: 1 <= m <= 32");
  std::call_once(once[static_cast<std::size_t>(m)],
                 [m] { rules[static_cast<std::size_t>(m)] = compute_laguerre(m); });
  return rules[static_cast<std::size_t>(m)];
}

const QuadratureRule& gauss_legendre(int m) {
  static std::array<QuadratureRule, 33> rules;
  static std::array<std::once_flag, 33> once;
  if (m < 1 || m > 32) throw std::out_of_range("gauss_legendre: 1 <= m <= 32");
  std::call_once(once[static_cast<std::size_t>(m)],
                 [m] { rules[static_cast<std::size_t>(m)] = compute(m); });
  return rules[static_cast<std::size_t>(m)];
}

}  // namespace covsim
