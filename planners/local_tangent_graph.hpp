#pragma once
// What a sensor reading tells about the way to a goal (Kamon, Rivlin and Rimon 1998): how far
// the robot can move in a direction, the nodes of the local tangent graph (the goal, when the
// way to it is free within range, and the discontinuity points of the visible boundary), and
// the closest point to the goal of the visible free region (d_reach). The reading's contacts
// are exact; its range pieces may carry noise.
#include <optional>
#include <vector>

#include "planners/sensor_reading.hpp"

namespace covsim {

struct FreeRay {
  double distance;                       // free travel along the direction (may be infinite)
  std::optional<std::uint32_t> blocker;  // the ring in the way, if any
};

// How far the robot can move from r.position along the unit direction u: 0 when a wall it
// touches faces the direction (free space lies on the left of every boundary edge); else
// the nearest sensed piece the ray crosses beyond `tolerance`.
FreeRay free_ray(const SensorReading& r, Vec2 u, double tolerance);

// The contact edge to walk along in direction dir (+1 along the ring's edges, -1 against
// them): the one whose far end in that direction is not where the robot stands.
std::optional<ContactEdge> walking_edge(const SensorReading& r, int dir, double tolerance);

struct TangentNode {
  Vec2 point;
  double heuristic;        // d(x, node) + d(node, goal)
  bool is_goal;            // the goal itself, or the free point straight toward it within range
  std::uint32_t ring = 0;  // the obstacle a discontinuity point lies on
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

// The point of the visible free region closest to the goal, the sensed boundary of the
// followed ring excluded (those points count toward d_followed instead): the free point
// straight toward the goal (the robot's own position for a contact sensor that may move that
// way), the discontinuity points and the shadow segments between them, and the visible
// pieces of other obstacles.
ReachPoint reach_point(const SensorReading& r, Vec2 goal, std::uint32_t followed, double tolerance);

}  // namespace covsim
