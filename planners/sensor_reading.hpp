#pragma once
// What a robot's sensors give a planner at one instant, and only what they measure: the part
// of ∂Ω visible within the sensing range, as points and segments, and the wall segments the
// robot touches (a contact sensor feels a wall's direction, which is how a robot with range
// 0 follows a wall). No obstacle, ring or edge ids: which sensed points belong to one
// obstacle is for the planner to infer from geometry.
#include <optional>
#include <vector>

#include "core/random_stream.hpp"
#include "geometry/visibility.hpp"

namespace covsim {

// A touched wall segment, free space on the left of a -> b.
struct ContactEdge {
  Vec2 a, b;
};

// A visible stretch of one wall, a -> b counter-clockwise as seen from the robot (so free
// space is on its left, the robot's side).
struct SensedPiece {
  Vec2 a, b;
};

struct SensedBoundary {
  // In counter-clockwise order of direction from the robot. Consecutive pieces whose ends
  // coincide (the last and the first included) are one continuous stretch of boundary.
  std::vector<SensedPiece> pieces;
  // Where the visible boundary jumps: a piece's end that is not the next piece's start
  // (an occluding vertex, the point behind it, or where a wall leaves the sensing range).
  std::vector<Vec2> discontinuities;
};

struct SensorReading {
  Vec2 position;
  // Where the range reading (visible) was taken: the position, unless the sensor reads less
  // often than the robot moves or the last reading was lost. Its discontinuities, shadows
  // and range describe the view from there; its pieces are walls wherever the robot stands.
  Vec2 origin;
  double range = 0.0;  // may be infinite
  std::vector<ContactEdge> contacts;

  // The visible boundary within the range. A reading from sense() takes it from Ω when first
  // asked for, so a planner that decides without it (on an open way, say) costs no
  // visibility query; the answer is the same either way.
  const SensedBoundary& visible() const;
  SensedBoundary& visible();
  void set_visible(SensedBoundary v);
  // Whether nothing the sensors report lies within `clearance` of the straight way from the
  // position toward p, up to the range (p itself if nearer): a line of sight that is clear
  // by a margin. Answered from Ω for a reading from sense(), from its pieces otherwise.
  bool open_toward(Vec2 p, double clearance) const;

 private:
  friend SensorReading sense(const Environment& env, Vec2 p, double range);
  mutable std::optional<SensedBoundary> visible_;
  // Set in a reading from sense() whose visible boundary is still to be taken.
  const Environment* environment_ = nullptr;
};

// A reading taken in the environment at p: what an ideal range and contact sensor report.
// Its visible boundary is taken when first asked for (the environment must outlive it).
SensorReading sense(const Environment& env, Vec2 p, double range);

// The boundary edges touching p (what a contact sensor reports).
std::vector<ContactEdge> contacts_at(const Environment& env, Vec2 p);

// The reading as a robot that believes it stands `offset` from where it does maps it: what it
// measured relative to itself moves with it (its position, the view's origin, the walls it
// sees and touches). The visible boundary is taken first.
void shift(SensorReading& r, Vec2 offset);

// Gaussian range noise: every sensed point farther than `tolerance` from the robot moves
// along its ray from the robot by N(0, sigma²), never closer than the robot itself. A point
// shared by two joined pieces is one measurement and moves once, so the continuity of the
// visible boundary survives the noise; the discontinuities are the noisy pieces' ends.
// Contacts are left alone.
void add_range_noise(SensorReading& r, RandomStream& rng, double sigma, double tolerance);

}  // namespace covsim
