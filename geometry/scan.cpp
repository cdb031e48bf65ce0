#include "geometry/scan.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace covsim {

namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

double angle_of(Vec2 o, Vec2 p) {
  return std::atan2(p.y - o.y, p.x - o.x);
}

// The counter-clockwise angle from direction a to direction b about o, in [0, 2π).
double turn_between(Vec2 o, Vec2 a, Vec2 b) {
  double t = angle_of(o, b) - angle_of(o, a);
  while (t < 0.0)
    t += kTurn;
  while (t >= kTurn)
    t -= kTurn;
  return t;
}

// The fan's vertices for the directions from b's to a's (counter-clockwise) where no piece
// lies: free to the range (chords of its circle) when the reading saw no wall there, else
// nothing beyond the origin (the robot stands on the boundary and looks into the wall).
// b and a are the pieces' ends, or, for an end at the origin, a point along its piece.
void fill_gap(const Environment& env, Vec2 o, double range, Vec2 b, Vec2 a, double gap,
              std::vector<Vec2>& fan) {
  const double from = angle_of(o, b);
  const double mid = from + 0.5 * gap;
  const Vec2 dir{std::cos(mid), std::sin(mid)};
  if (!std::isfinite(range) || env.ray_cast(o, dir, range)) {
    fan.push_back(o);
    return;
  }
  const auto at = [&](double angle) {
    return Vec2{o.x + range * std::cos(angle), o.y + range * std::sin(angle)};
  };
  if (distance(o, b) < range) fan.push_back(at(from));
  const double step = kTurn / kFanChordsPerTurn;
  const int chords = static_cast<int>(std::ceil(gap / step));
  for (int k = 1; k < chords; ++k)
    fan.push_back(at(from + gap * k / chords));
  if (distance(o, a) < range) fan.push_back(at(from + gap));
}

constexpr double kSameRay = 1e-9;  // rad: consecutive pieces on one ray (an occluding vertex)

// The fan of pieces [first, last) of a reading: with every piece, the whole turn; else the
// sector from the first piece's start to the next piece's (pieces[last], cyclically), so
// that the parts of a split reading join.
std::vector<Vec2> fan_of(const Environment& env, Vec2 o, double range,
                         const std::vector<VisiblePiece>& pieces, std::size_t first,
                         std::size_t last) {
  std::vector<Vec2> fan;
  if (range == 0.0) return fan;
  const bool full_turn = first == 0 && last == pieces.size();
  if (pieces.empty()) {
    if (std::isfinite(range)) {
      for (int k = 0; k < kFanChordsPerTurn; ++k) {
        const double a = kTurn * k / kFanChordsPerTurn;
        fan.push_back({o.x + range * std::cos(a), o.y + range * std::sin(a)});
      }
    }
    return fan;
  }
  if (!full_turn) fan.push_back(o);
  for (std::size_t k = first; k < last; ++k) {
    fan.push_back(pieces[k].a);
    fan.push_back(pieces[k].b);
    const VisiblePiece& next = pieces[(k + 1) % pieces.size()];
    // An end at the origin (the robot stands on a wall, or at a corner: within the
    // tolerance, as the visibility looks from there) has no direction of its own: its piece's
    // other end gives it.
    const double tol = env.tolerance();
    const bool b_here = within(pieces[k].b, o, tol), a_here = within(next.a, o, tol);
    if (within(pieces[k].b, next.a, tol) || (b_here && a_here)) continue;
    const Vec2 b = b_here ? pieces[k].a : pieces[k].b, a = a_here ? next.b : next.a;
    if (within(b, o, tol) || within(a, o, tol)) continue;  // a piece seen as a point
    const double gap = turn_between(o, b, a);
    if (gap < kSameRay || gap > kTurn - kSameRay) continue;
    fill_gap(env, o, range, b, a, gap, fan);
  }
  return fan;
}

}  // namespace

Scan take_scan(const Environment& env, Vec2 origin, double range) {
  Scan s;
  s.origin = origin;
  s.range = range;
  if (range > 0.0) s.pieces = visible_boundary(env, origin, range).pieces;
  s.fan = fan_of(env, origin, range, s.pieces, 0, s.pieces.size());
  return s;
}

std::vector<Scan> split_scan(const Environment& env, Scan scan, std::uint32_t max_bytes) {
  std::vector<Scan> out;
  if (scan.bytes() <= max_bytes) {
    out.push_back(std::move(scan));
    return out;
  }
  const std::size_t per = std::max<std::size_t>(1, (max_bytes - 8 - 2) / (8 + 8 + 4));
  for (std::size_t first = 0; first < scan.pieces.size(); first += per) {
    Scan part;
    part.origin = scan.origin;
    part.range = scan.range;
    const std::size_t last = std::min(scan.pieces.size(), first + per);
    part.pieces.assign(scan.pieces.begin() + static_cast<std::ptrdiff_t>(first),
                       scan.pieces.begin() + static_cast<std::ptrdiff_t>(last));
    part.fan = fan_of(env, scan.origin, scan.range, scan.pieces, first, last);
    out.push_back(std::move(part));
  }
  return out;
}

void add_range_noise(Scan& scan, RandomStream& rng, double sigma, double tolerance) {
  if (!(sigma > 0.0)) return;
  // Each measured point once, drawn in the order the pieces meet it.
  std::map<std::pair<double, double>, Vec2> moved;
  const auto jitter = [&](Vec2 q) {
    const auto key = std::make_pair(q.x, q.y);
    if (const auto it = moved.find(key); it != moved.end()) return it->second;
    const Vec2 d = q - scan.origin;
    const double n = norm(d);
    const Vec2 out =
        n <= tolerance ? q : scan.origin + (std::max(0.0, n + rng.normal(0.0, sigma)) / n) * d;
    moved.emplace(key, out);
    return out;
  };
  for (VisiblePiece& p : scan.pieces) {
    p.a = jitter(p.a);
    p.b = jitter(p.b);
  }
  for (Vec2& v : scan.fan)
    if (const auto it = moved.find(std::make_pair(v.x, v.y)); it != moved.end()) v = it->second;
}

void shift(Scan& scan, Vec2 offset) {
  scan.origin = scan.origin + offset;
  for (VisiblePiece& p : scan.pieces) {
    p.a = p.a + offset;
    p.b = p.b + offset;
  }
  for (Vec2& v : scan.fan)
    v = v + offset;
}

}  // namespace covsim
