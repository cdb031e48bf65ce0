#pragma once
// A point or vector in the plane. Plain doubles: the hot geometry code works on these.
#include <cmath>

namespace covsim {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2() = default;
  constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}

  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
  friend constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
  constexpr Vec2& operator+=(Vec2 b) {
    x += b.x;
    y += b.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 b) {
    x -= b.x;
    y -= b.y;
    return *this;
  }
  friend constexpr bool operator==(Vec2, Vec2) = default;
};

constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
// z-component of the 3D cross product: > 0 when b is counter-clockwise from a.
constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
constexpr double norm2(Vec2 a) {
  return dot(a, a);
}
inline double norm(Vec2 a) {
  return std::hypot(a.x, a.y);
}
inline double distance(Vec2 a, Vec2 b) {
  return norm(a - b);
}
// How far distance(a, b) may be off through the rounding of a and b's coordinates (a few
// units in the last place of the largest): what a check of a length against a bound allows,
// so that a step of 1e-7 m between points 6 m from the origin passes as 1e-7 m.
inline double distance_rounding(Vec2 a, Vec2 b) {
  const double m = std::fmax(std::fmax(std::fabs(a.x), std::fabs(a.y)),
                             std::fmax(std::fabs(b.x), std::fabs(b.y)));
  return 8.0 * 2.220446049250313e-16 * m;  // 8 × DBL_EPSILON × m
}
// distance(a, b) <= r, the same answer bit for bit, without the hypot when a coordinate's
// difference alone exceeds r (hypot is never below either coordinate's magnitude): most
// tolerance tests in sensing and planning are of points far apart.
inline bool within(Vec2 a, Vec2 b, double r) {
  const Vec2 d = a - b;
  if (std::fabs(d.x) > r || std::fabs(d.y) > r) return false;
  return norm(d) <= r;
}
// distance(a, b) > r in the same way (not !within: both are false for NaN).
inline bool beyond(Vec2 a, Vec2 b, double r) {
  const Vec2 d = a - b;
  if (std::fabs(d.x) > r || std::fabs(d.y) > r) return true;
  return norm(d) > r;
}
constexpr Vec2 perp(Vec2 a) {
  return {-a.y, a.x};
}  // rotated +90 degrees
inline bool is_finite(Vec2 a) {
  return std::isfinite(a.x) && std::isfinite(a.y);
}

// Closest point to p on the segment [a, b], and its parameter in [0, 1].
struct SegmentProjection {
  Vec2 point;
  double t;
};
inline SegmentProjection project_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = norm2(d);
  double t = len2 > 0.0 ? dot(p - a, d) / len2 : 0.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  return {a + t * d, t};
}

// Distance between the segments [a, b] and [c, d]: 0 when they cross, else the least distance
// from an end of one to the other.
inline double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a);
  const double o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
  if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) &&
      ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)))
    return 0.0;
  const auto to = [](Vec2 p, Vec2 s, Vec2 e) {
    return distance(p, project_to_segment(p, s, e).point);
  };
  const double ab = to(a, c, d) < to(b, c, d) ? to(a, c, d) : to(b, c, d);
  const double cd = to(c, a, b) < to(d, a, b) ? to(c, a, b) : to(d, a, b);
  return ab < cd ? ab : cd;
}

struct Box {
  Vec2 lo{INFINITY, INFINITY};
  Vec2 hi{-INFINITY, -INFINITY};
  void add(Vec2 p) {
    lo = {std::fmin(lo.x, p.x), std::fmin(lo.y, p.y)};
    hi = {std::fmax(hi.x, p.x), std::fmax(hi.y, p.y)};
  }
  bool empty() const { return lo.x > hi.x || lo.y > hi.y; }
  bool overlaps(const Box& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y;
  }
  bool contains(const Box& o) const {
    return lo.x <= o.lo.x && o.hi.x <= hi.x && lo.y <= o.lo.y && o.hi.y <= hi.y;
  }
  Vec2 size() const { return hi - lo; }
  friend bool operator==(const Box&, const Box&) = default;
};

}  // namespace covsim
