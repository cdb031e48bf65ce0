#pragma once
// What a robot's sensors give a planner at one instant: the part of ∂Ω visible within the
// sensing range, and the boundary edges it touches (a contact sensor feels the wall's
// direction, which is how a robot with range 0 follows a wall).
#include <vector>

#include "core/geometry/visibility.hpp"
#include "core/random_stream.hpp"

namespace covsim {

struct ContactEdge {
  std::uint32_t edge;   // boundary edge id
  std::uint32_t ring;   // which obstacle (0: the outer boundary, h + 1: hole h)
  std::uint32_t index;  // the edge's place in its ring, in the ring's direction
  Vec2 a, b;            // free space on the left of a -> b
};

struct SensorReading {
  Vec2 position;
  double range = 0.0;  // may be infinite
  VisibleBoundary visible;
  std::vector<ContactEdge> contacts;
  // Which obstacle each visible piece, and each discontinuity point, belongs to (parallel to
  // visible.pieces and visible.discontinuities).
  std::vector<std::uint32_t> piece_rings;
  std::vector<std::uint32_t> discontinuity_rings;
};

// A reading taken in the environment at p: what an ideal range and contact sensor report.
SensorReading sense(const Environment& env, Vec2 p, double range);

// The boundary edges touching p (what a contact sensor reports).
std::vector<ContactEdge> contacts_at(const Environment& env, Vec2 p);

// Gaussian range noise: every sensed point (piece ends, discontinuity points) farther than
// `tolerance` from the robot moves along its ray from the robot by N(0, sigma²), never
// closer than the robot itself. Contacts are left alone.
void add_range_noise(SensorReading& r, RandomStream& rng, double sigma, double tolerance);

}  // namespace covsim
