#pragma once
// One range reading as a mapping robot keeps it: the boundary of Ω it saw within range from
// where it stood, and the region that reading shows to be free (its fan).
#include <cstdint>
#include <vector>

#include "core/random_stream.hpp"
#include "geometry/visibility.hpp"

namespace covsim {

struct Scan {
  Vec2 origin;
  double range = 0.0;
  std::vector<VisiblePiece> pieces;  // counter-clockwise as seen from origin
  // The free region the reading shows: a polygon star-shaped about origin, through the
  // visible pieces, closed in directions where no wall lies within range by chords of the
  // range circle (inscribed, so it stays inside what was seen). Empty for range 0.
  std::vector<Vec2> fan;
  // Its size in a message: the origin (two float32, 8 bytes), the number of pieces (2
  // bytes), and each piece's two end points (8 bytes each) with the wall it lies on (4
  // bytes); the range is every robot's.
  std::uint32_t bytes() const {
    return 8 + 2 + static_cast<std::uint32_t>(pieces.size()) * (8 + 8 + 4);
  }
};

// Chords of the range circle subtend at most this angle (2π / 64): their sagitta is at most
// 0.12% of the range, the area they leave out 0.16% of a full circle's.
inline constexpr int kFanChordsPerTurn = 64;

// The reading from origin (in Ω) within range (finite or infinite; 0: nothing).
Scan take_scan(const Environment& env, Vec2 origin, double range);

// A scan whose message would exceed max_bytes, cut into scans of consecutive pieces that
// each fit (each with the fan of its pieces alone); scans that fit are returned as they are.
std::vector<Scan> split_scan(const Environment& env, Scan scan, std::uint32_t max_bytes);

// The reading as a noisy range sensor gives it: every wall point it measured farther than
// `tolerance` from the origin moves along its ray by N(0, sigma²) (never behind the origin),
// a point two pieces share once; the fan moves with them (its chords at the range are no
// measurement and stay).
void add_range_noise(Scan& scan, RandomStream& rng, double sigma, double tolerance);

// The reading as a robot that believes it stands `offset` from where it does places it.
void shift(Scan& scan, Vec2 offset);

}  // namespace covsim
