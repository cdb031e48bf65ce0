#include "geometry/convex_polygon.hpp"

namespace covsim {

void clip(const ConvexPolygon& in, const HalfPlane& h, ConvexPolygon& out) {
  out.clear();
  const std::size_t n = in.size();
  if (n == 0) return;
  Vec2 prev = in[n - 1];
  double dprev = h.signed_distance(prev);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 cur = in[i];
    const double dcur = h.signed_distance(cur);
    if (dcur <= 0.0) {
      if (dprev > 0.0 && dcur < 0.0) out.push_back(prev + (dprev / (dprev - dcur)) * (cur - prev));
      out.push_back(cur);
    } else if (dprev <= 0.0) {
      if (dprev < 0.0) out.push_back(prev + (dprev / (dprev - dcur)) * (cur - prev));
    }
    prev = cur;
    dprev = dcur;
  }
  if (out.size() < 3) out.clear();
}

Moments polygon_moments(const std::vector<Vec2>& poly, Vec2 r) {
  // Green's theorem on each edge of the polygon shifted by -r.
  Moments m;
  double a2 = 0.0, sx = 0.0, sy = 0.0, ixx = 0.0, iyy = 0.0;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = poly[i] - r;
    const Vec2 q = poly[(i + 1) % n] - r;
    const double c = cross(p, q);
    a2 += c;
    sx += (p.x + q.x) * c;
    sy += (p.y + q.y) * c;
    ixx += (p.x * p.x + p.x * q.x + q.x * q.x) * c;
    iyy += (p.y * p.y + p.y * q.y + q.y * q.y) * c;
  }
  m.mass = 0.5 * a2;
  m.first = {sx / 6.0, sy / 6.0};
  m.second = (ixx + iyy) / 12.0;
  return m;
}

double signed_area(const std::vector<Vec2>& poly) {
  double a2 = 0.0;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i)
    a2 += cross(poly[i], poly[(i + 1) % n]);
  return 0.5 * a2;
}

}  // namespace covsim
