#pragma once
// What a sensor reading tells about the way to a goal (Kamon, Rivlin and Rimon 1998): how far
// the robot can move in a direction, the stretches of boundary it sees as one (the sensed
// boundary between two discontinuities), the nodes of the local tangent graph (the goal,
// when the way to it is free within range, and the discontinuity points of the visible
// boundary), and the closest point to the goal of the visible free region (d_reach). The
// reading's contacts are exact; its range pieces may carry noise.
#include <functional>
#include <optional>
#include <vector>

#include "planners/sensor_reading.hpp"

namespace covsim {

struct FreeRay {
  double distance;  // free travel along the direction (may be infinite)
  // The sensed boundary point in the way: the robot's own position when a touched wall
  // faces the direction; empty when nothing sensed blocks it.
  std::optional<Vec2> blocked_at;
};

// How far the robot can move from r.position along the unit direction u: 0 when a wall it
// touches faces the direction (free space lies on the left of every boundary edge); else
// the nearest sensed piece the ray crosses beyond `tolerance`.
FreeRay free_ray(const SensorReading& r, Vec2 u, double tolerance);

// The contact edge to walk along in direction dir (+1 with free space on the left, -1 on the
// right): the one whose far end in that direction is not where the robot stands.
std::optional<ContactEdge> walking_edge(const SensorReading& r, int dir, double tolerance);

// A stretch of boundary seen without a jump: consecutive sensed pieces, each starting where
// the last ended. Its points run counter-clockwise as seen from the robot, which is the
// direction +1 (free space on the left); its ends are discontinuity points.
struct SensedChain {
  std::vector<Vec2> points;
  std::size_t first_piece = 0, piece_count = 0;  // reading's pieces, cyclically
  bool closed = false;  // the whole visible boundary, one loop round the robot
  bool holds_piece(std::size_t k, std::size_t pieces) const {
    return (k + pieces - first_piece) % pieces < piece_count;
  }
};

std::vector<SensedChain> sensed_chains(const SensorReading& r, double tolerance);

// A point of a polyline: the segment it lies on (from points[segment]) and the point.
struct PolylinePlace {
  std::size_t segment = 0;
  Vec2 point;
  double distance = 0.0;  // from the point it was found for
};
PolylinePlace closest_place(const std::vector<Vec2>& points, Vec2 p);

struct TangentNode {
  Vec2 point;
  double heuristic;  // d(x, node) + d(node, goal)
  bool is_goal;      // the goal itself, or the free point straight toward it within range
};

// The nodes of the local tangent graph: the goal, when nothing sensed blocks the way to it
// within the range, and every discontinuity point O farther than `tolerance` from the robot
// with d(O, goal) < bound (a node no closer than bound is left out).
std::vector<TangentNode> tangent_nodes(const SensorReading& r, Vec2 goal, double bound,
                                       double tolerance);

struct ReachPoint {
  Vec2 point;
  double distance;  // d_reach: from the goal; infinite when nothing qualifies
};

// The point of the visible free region closest to the goal, the followed stretch of
// boundary excluded (its points count toward d_followed instead): the free point straight
// toward the goal (the robot's own position for a contact sensor that may move that way),
// the discontinuity points and the shadow segments between them, and every other visible
// piece.
// `admissible`, if given, leaves out the points it rejects.
ReachPoint reach_point(const SensorReading& r, Vec2 goal, const SensedChain* followed,
                       double tolerance, const std::function<bool(Vec2)>& admissible = {});

}  // namespace covsim
