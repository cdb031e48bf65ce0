#include "planners/sensor_reading.hpp"

namespace covsim {

SensorReading sense(const Environment& env, Vec2 p, double range) {
  SensorReading r;
  r.position = p;
  r.range = range;
  r.visible = visible_boundary(env, p, range);
  for (const VisiblePiece& piece : r.visible.pieces)
    r.piece_rings.push_back(env.boundary()[piece.edge].ring);
  for (std::uint32_t e : env.edges_at(p)) {
    const BoundaryEdge& be = env.boundary()[e];
    r.contacts.push_back(ContactEdge{e, be.ring, be.index, be.a, be.b});
  }
  return r;
}

}  // namespace covsim
