#pragma once
// What a robot learns of an obstacle by going round it: the boundary points it touched or
// sensed, in the order it passed them, closed into a polygon. Nothing but geometry: whether
// the obstacle encloses a goal (the goal lies inside it, or outside the outer boundary) is a
// point-in-polygon test on what was recorded, and its point closest to the goal (the
// projection) is the closest recorded boundary point.
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

// A place on a recorded obstacle: the point and its arc length from ring[0] in ring order.
struct RingPlace {
  Vec2 point;
  double arc = 0.0;
};

class RecordedObstacle {
 public:
  // `walked`: the boundary points in the order passed, walking in direction dir (+1 with
  // free space on the left, -1 on the right).
  RecordedObstacle(const std::vector<Vec2>& walked, int dir, double tolerance);

  // In ring order: free space on the left of every edge.
  const std::vector<Vec2>& ring() const { return ring_; }
  double perimeter() const { return perimeter_; }
  // Free space inside (counter-clockwise): the outer boundary as seen from within.
  bool outer() const { return outer_; }
  // Whether p lies beyond it, away from the free space the robot walked in: inside a hole,
  // or outside the outer boundary. A point on it is not enclosed.
  bool encloses(Vec2 p) const;
  bool on_boundary(Vec2 p, double within) const;
  RingPlace closest(Vec2 p) const;
  // The length walked along it from `from` to `to` in direction dir.
  double arc(RingPlace from, RingPlace to, int dir) const;

 private:
  std::vector<Vec2> ring_;
  std::vector<double> start_arc_;  // arc length at each ring vertex
  double perimeter_ = 0.0;
  double tolerance_;
  bool outer_ = false;
};

}  // namespace covsim
