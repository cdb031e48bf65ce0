#include "planners/sensor_reading.hpp"

#include <algorithm>

namespace covsim {

SensorReading sense(const Environment& env, Vec2 p, double range) {
  SensorReading r;
  r.position = p;
  r.range = range;
  r.visible = visible_boundary(env, p, range);
  for (const VisiblePiece& piece : r.visible.pieces)
    r.piece_rings.push_back(env.boundary()[piece.edge].ring);
  for (std::uint32_t e : r.visible.discontinuity_edges)
    r.discontinuity_rings.push_back(env.boundary()[e].ring);
  r.contacts = contacts_at(env, p);
  return r;
}

std::vector<ContactEdge> contacts_at(const Environment& env, Vec2 p) {
  std::vector<ContactEdge> out;
  for (std::uint32_t e : env.edges_at(p)) {
    const BoundaryEdge& be = env.boundary()[e];
    out.push_back(ContactEdge{e, be.ring, be.index, be.a, be.b});
  }
  return out;
}

void add_range_noise(SensorReading& r, RandomStream& rng, double sigma, double tolerance) {
  const auto jitter = [&](Vec2& q) {
    const Vec2 d = q - r.position;
    const double n = norm(d);
    if (n <= tolerance) return;
    q = r.position + (std::max(0.0, n + rng.normal(0.0, sigma)) / n) * d;
  };
  for (VisiblePiece& piece : r.visible.pieces) {
    jitter(piece.a);
    jitter(piece.b);
  }
  for (Vec2& o : r.visible.discontinuities)
    jitter(o);
}

}  // namespace covsim
