#include "planners/sensor_reading.hpp"

#include <algorithm>

namespace covsim {

namespace {
// The jumps of the visible boundary, as visible_boundary finds them: after piece k when its
// end is not piece k + 1's start (cyclically).
std::vector<bool> jumps(const std::vector<SensedPiece>& pieces, double tolerance) {
  const std::size_t n = pieces.size();
  std::vector<bool> out(n, false);
  for (std::size_t k = 0; k < n; ++k)
    out[k] = beyond(pieces[k].b, pieces[(k + 1) % n].a, tolerance);
  return out;
}

std::vector<Vec2> discontinuities(const std::vector<SensedPiece>& pieces,
                                  const std::vector<bool>& jump) {
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (!jump[k]) continue;
    out.push_back(pieces[k].b);
    out.push_back(pieces[(k + 1) % pieces.size()].a);
  }
  return out;
}
}  // namespace

SensorReading sense(const Environment& env, Vec2 p, double range) {
  SensorReading r;
  r.position = r.origin = p;
  r.range = range;
  r.contacts = contacts_at(env, p);
  if (range > 0.0) {
    r.environment_ = &env;  // the visible boundary when first asked for
  } else {
    r.visible_.emplace();  // a contact sensor feels, it does not see
  }
  return r;
}

const SensedBoundary& SensorReading::visible() const {
  if (!visible_) {
    SensedBoundary out;
    if (environment_ != nullptr) {
      const VisibleBoundary v = visible_boundary(*environment_, origin, range);
      out.pieces.reserve(v.pieces.size());
      for (const VisiblePiece& piece : v.pieces)
        out.pieces.push_back(SensedPiece{piece.a, piece.b});
      out.discontinuities = v.discontinuities;
    }
    visible_ = std::move(out);
  }
  return *visible_;
}

SensedBoundary& SensorReading::visible() {
  static_cast<const SensorReading&>(*this).visible();
  environment_ = nullptr;  // the caller may change the pieces: they are the reading now
  return *visible_;
}

void SensorReading::set_visible(SensedBoundary v) {
  visible_ = std::move(v);
  environment_ = nullptr;
}

bool SensorReading::open_toward(Vec2 p, double clearance) const {
  const double d = distance(p, position);
  if (!(d > 0.0)) return false;
  const Vec2 end = d <= range ? p : position + (range / d) * (p - position);
  if (environment_ != nullptr) return environment_->clear_of_boundary(position, end, clearance);
  if (!contacts.empty()) return false;
  for (const SensedPiece& piece : visible().pieces) {
    if (!(segment_distance(position, end, piece.a, piece.b) > clearance)) return false;
  }
  return true;
}

std::vector<ContactEdge> contacts_at(const Environment& env, Vec2 p) {
  std::vector<ContactEdge> out;
  for (std::uint32_t e : env.edges_at(p))
    out.push_back(ContactEdge{env.boundary()[e].a, env.boundary()[e].b});
  return out;
}

void shift(SensorReading& r, Vec2 offset) {
  SensedBoundary& v = r.visible();
  for (SensedPiece& piece : v.pieces) {
    piece.a = piece.a + offset;
    piece.b = piece.b + offset;
  }
  for (Vec2& d : v.discontinuities)
    d = d + offset;
  for (ContactEdge& c : r.contacts) {
    c.a = c.a + offset;
    c.b = c.b + offset;
  }
  r.position = r.position + offset;
  r.origin = r.origin + offset;
}

void add_range_noise(SensorReading& r, RandomStream& rng, double sigma, double tolerance) {
  if (sigma <= 0.0) return;
  std::vector<SensedPiece>& pieces = r.visible().pieces;
  const std::vector<bool> jump = jumps(pieces, tolerance);
  const auto jitter = [&](Vec2 q) {
    const Vec2 d = q - r.position;
    const double n = norm(d);
    if (n <= tolerance) return q;
    return r.position + (std::max(0.0, n + rng.normal(0.0, sigma)) / n) * d;
  };
  const std::size_t n = pieces.size();
  for (std::size_t k = 0; k < n; ++k) {
    // A start joined to the previous piece's end is measured with it.
    if (jump[(k + n - 1) % n]) pieces[k].a = jitter(pieces[k].a);
    pieces[k].b = jitter(pieces[k].b);
    if (k + 1 < n && !jump[k]) pieces[k + 1].a = pieces[k].b;
  }
  if (n > 1 && !jump[n - 1]) pieces[0].a = pieces[n - 1].b;
  r.visible().discontinuities = discontinuities(pieces, jump);
}

}  // namespace covsim
