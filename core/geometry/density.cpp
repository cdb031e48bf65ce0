#include "core/geometry/density.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry/quadrature.hpp"

namespace covsim {

namespace {
constexpr int kMixturePoints = 8;   // exact to degree 14 on each triangle
constexpr int kBilinearPoints = 3;  // exact to degree 4: bilinear times |x - r|^2

double mixture_value(const std::vector<GaussianComponent>& cs, double floor, Vec2 x) {
  double v = floor;
  for (const auto& c : cs)
    v += c.weight * std::exp(-norm2(x - c.mean) / (2.0 * c.sigma * c.sigma));
  return v;
}

// Calls f on triangles covering the triangle (a, b, c), halving its longest edge until no
// edge is longer than max_width.
template <class F>
void subdivide(Vec2 a, Vec2 b, Vec2 c, double max_width, const F& f, int depth = 0) {
  const double ab = norm2(b - a), bc = norm2(c - b), ca = norm2(a - c);
  const double longest = std::max({ab, bc, ca});
  if (longest <= max_width * max_width || depth > 40) {
    f(a, b, c);
    return;
  }
  if (longest == ab) {
    const Vec2 m = 0.5 * (a + b);
    subdivide(a, m, c, max_width, f, depth + 1);
    subdivide(m, b, c, max_width, f, depth + 1);
  } else if (longest == bc) {
    const Vec2 m = 0.5 * (b + c);
    subdivide(a, b, m, max_width, f, depth + 1);
    subdivide(a, m, c, max_width, f, depth + 1);
  } else {
    const Vec2 m = 0.5 * (c + a);
    subdivide(a, b, m, max_width, f, depth + 1);
    subdivide(m, b, c, max_width, f, depth + 1);
  }
}
}  // namespace

Density Density::uniform(double value) {
  if (!std::isfinite(value) || value <= 0.0)
    throw std::invalid_argument("a uniform density must be positive and finite");
  return Density(Uniform{value});
}

Density Density::gaussian_mixture(std::vector<GaussianComponent> components, double floor) {
  if (!std::isfinite(floor) || floor < 0.0)
    throw std::invalid_argument("floor must be finite and non-negative");
  double max_width = INFINITY;
  for (std::size_t i = 0; i < components.size(); ++i) {
    const auto& c = components[i];
    if (!is_finite(c.mean) || !std::isfinite(c.sigma) || !std::isfinite(c.weight)) {
      throw std::invalid_argument("component " + std::to_string(i) + " has a non-finite value");
    }
    if (c.sigma <= 0.0)
      throw std::invalid_argument("component " + std::to_string(i) + ": sigma must be positive");
    if (c.weight < 0.0)
      throw std::invalid_argument("component " + std::to_string(i) +
                                  ": weight must be non-negative");
    max_width = std::min(max_width, c.sigma);
  }
  return Density(Mixture{std::move(components), floor, max_width});
}

Density Density::raster(Raster r) {
  return Density(std::move(r));
}

double Density::operator()(Vec2 x) const {
  return std::visit(
      [&](const auto& m) -> double {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, Uniform>) return m.value;
        if constexpr (std::is_same_v<T, Mixture>) return mixture_value(m.components, m.floor, x);
        if constexpr (std::is_same_v<T, Raster>) return m(x);
      },
      model_);
}

Moments Density::integrate(const ConvexPolygon& piece, Vec2 r) const {
  if (piece.size() < 3) return {};
  if (const auto* u = std::get_if<Uniform>(&model_))
    return polygon_moments(piece, r).scaled(u->value);
  if (const auto* m = std::get_if<Mixture>(&model_)) return integrate_mixture(*m, piece, r);
  return integrate_raster(std::get<Raster>(model_), piece, r);
}

Moments Density::integrate_mixture(const Mixture& m, const ConvexPolygon& piece, Vec2 r) const {
  Moments out;
  const auto f = [&](Vec2 x) { return mixture_value(m.components, m.floor, x); };
  for (std::size_t k = 1; k + 1 < piece.size(); ++k) {
    subdivide(piece[0], piece[k], piece[k + 1], m.max_width, [&](Vec2 a, Vec2 b, Vec2 c) {
      out += triangle_moments(a, b, c, r, f, kMixturePoints);
    });
  }
  return out;
}

Moments Density::integrate_raster(const Raster& m, const ConvexPolygon& piece, Vec2 r) const {
  // Clip the piece to each raster cell (or bilinear patch) it overlaps; the density is a
  // polynomial on each.
  Box box;
  for (Vec2 p : piece)
    box.add(p);
  const int cx = m.interpolation == Raster::Interpolation::constant ? m.nx : m.nx - 1;
  const int cy = m.interpolation == Raster::Interpolation::constant ? m.ny : m.ny - 1;
  const Vec2 cell{m.extent.size().x / cx, m.extent.size().y / cy};
  // Outside the extent the border cells extend outwards (the loader requires the extent
  // to cover Ω, so this only matters for rounding at the edge).
  const auto index = [](double v, int n) {
    return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1);
  };
  const int i0 = index((box.lo.x - m.extent.lo.x) / cell.x, cx),
            i1 = index((box.hi.x - m.extent.lo.x) / cell.x, cx);
  const int j0 = index((box.lo.y - m.extent.lo.y) / cell.y, cy),
            j1 = index((box.hi.y - m.extent.lo.y) / cell.y, cy);
  Moments out;
  ConvexPolygon a, b;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const double x0 = m.extent.lo.x + i * cell.x, y0 = m.extent.lo.y + j * cell.y;
      a = piece;
      if (i > 0) clip(a, HalfPlane{{-1, 0}, -x0}, b), a.swap(b);
      if (i < cx - 1) clip(a, HalfPlane{{1, 0}, x0 + cell.x}, b), a.swap(b);
      if (j > 0) clip(a, HalfPlane{{0, -1}, -y0}, b), a.swap(b);
      if (j < cy - 1) clip(a, HalfPlane{{0, 1}, y0 + cell.y}, b), a.swap(b);
      if (a.size() < 3) continue;
      if (m.interpolation == Raster::Interpolation::constant) {
        out += polygon_moments(a, r).scaled(m.at(i, j));
        continue;
      }
      const double v00 = m.at(i, j), v10 = m.at(i + 1, j), v01 = m.at(i, j + 1),
                   v11 = m.at(i + 1, j + 1);
      const auto f = [&](Vec2 x) {
        const double fx = (x.x - x0) / cell.x, fy = (x.y - y0) / cell.y;
        return (1 - fx) * (1 - fy) * v00 + fx * (1 - fy) * v10 + (1 - fx) * fy * v01 +
               fx * fy * v11;
      };
      for (std::size_t k = 1; k + 1 < a.size(); ++k)
        out += triangle_moments(a[0], a[k], a[k + 1], r, f, kBilinearPoints);
    }
  }
  return out;
}

}  // namespace covsim
