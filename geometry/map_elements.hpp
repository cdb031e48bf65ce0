#pragma once
// What a robot that does not know Ω may find out: its obstacles, each a hole of Ω or a pocket
// (a part of Ω's bounding box outside Ω's outer ring, bounded by a chain of the outer ring's
// edges and the box), and which of their walls it has seen. A robot knows an obstacle once it
// has seen every wall of it; its belief of Ω is the box (or Ω's outer ring) less the
// obstacles it knows, which always contains Ω: unknown space counts as free.
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "geometry/environment.hpp"
#include "geometry/scan.hpp"

namespace covsim {

struct MapElement {
  std::uint32_t ring = 0;  // 0: a pocket of the outer ring; h + 1: hole h
  // Its walls, as indices into Environment::boundary().
  std::vector<std::uint32_t> edges;
  // A pocket's chain of outer-ring vertices, from `first` to `last` (cyclically), both on
  // the box.
  std::uint32_t first = 0, last = 0;
};

// The holes of Ω, and with `pockets` the pockets of its outer ring, in that order.
std::vector<MapElement> map_elements(const Environment& env, bool pockets);

// Ω as a robot knowing the elements marked in `known` believes it: the outer ring with each
// unknown pocket replaced by the box's sides round it, less the known holes.
std::unique_ptr<Environment> believed_environment(const Environment& env,
                                                  const std::vector<MapElement>& elements,
                                                  const std::vector<bool>& known);

// The parts of Ω's walls a robot has seen, per boundary edge as parameter intervals.
class SeenWalls {
 public:
  explicit SeenWalls(const Environment& env);
  // Records the scan's pieces; returns whether an edge became seen whole.
  bool add(const Scan& scan);
  bool seen(std::uint32_t edge) const { return whole_[edge]; }
  bool seen(const MapElement& e) const;

 private:
  const Environment* env_;
  std::vector<std::vector<std::pair<double, double>>> intervals_;  // disjoint, sorted
  std::vector<bool> whole_;
};

}  // namespace covsim
