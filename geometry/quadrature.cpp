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
}  // namespace

const QuadratureRule& gauss_legendre(int m) {
  static std::array<QuadratureRule, 33> rules;
  static std::array<std::once_flag, 33> once;
  if (m < 1 || m > 32) throw std::out_of_range("gauss_legendre: 1 <= m <= 32");
  std::call_once(once[static_cast<std::size_t>(m)],
                 [m] { rules[static_cast<std::size_t>(m)] = compute(m); });
  return rules[static_cast<std::size_t>(m)];
}

}  // namespace covsim
