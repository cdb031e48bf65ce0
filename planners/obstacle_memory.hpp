#pragma once
// What a robot has learned of the obstacles it touched: the boundary edges its contact sensor
// felt, per ring, and which rings it has walked all the way round. A ring walked round is
// known exactly, so whether it encloses a goal (the goal lies in that obstacle, or outside
// the outer ring) is a point-in-polygon test, not a guess.
#include <cstdint>
#include <map>
#include <utility>

#include "planners/sensor_reading.hpp"

namespace covsim {

// A point on a ring and the index of the ring edge it lies on.
struct RingPoint {
  Vec2 point;
  std::uint32_t edge = 0;
};

class ObstacleMemory {
 public:
  explicit ObstacleMemory(double tolerance) : tolerance_(tolerance) {}

  void remember(const ContactEdge& e);
  // The robot has walked the whole ring: every edge of it has been felt.
  void close(std::uint32_t ring);
  bool complete(std::uint32_t ring) const;
  // For a complete ring: whether it encloses p (p in the hole, or p outside the outer ring).
  // A point on the ring is not enclosed.
  bool encloses(std::uint32_t ring, Vec2 p) const;
  // For a complete ring: its point closest to p.
  RingPoint closest(std::uint32_t ring, Vec2 p) const;
  // For a complete ring: the length walked along it from x (on edge i) to q (on edge j) in
  // direction dir (+1 along the edges, -1 against them).
  double arc(std::uint32_t ring, RingPoint x, RingPoint q, int dir) const;
  double perimeter(std::uint32_t ring) const;

 private:
  struct Ring {
    std::map<std::uint32_t, std::pair<Vec2, Vec2>> edges;  // by index in the ring
    std::uint32_t size = 0;                                // known once walked round
  };
  const Ring& ring(std::uint32_t r) const { return rings_.at(r); }

  double tolerance_;
  std::map<std::uint32_t, Ring> rings_;
};

}  // namespace covsim
