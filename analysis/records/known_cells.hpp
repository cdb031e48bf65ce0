#pragma once
// What the robots that mapped Ω knew of it over time, as map.csv holds it: each cell of Ω's
// known-area lattice (robot/mapping.hpp) whose centre lies in Ω, and when the robots' maps
// together first held it.
#include <cmath>
#include <filesystem>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

struct KnownCell {
  Vec2 centre;
  double since;  // s; infinite: never
};

struct KnownCells {
  double size = 0.0;  // m, a cell's side
  std::vector<KnownCell> cells;
  // With mapping.robot_maps (decentralized runs): per robot, when its own map first held each
  // cell, parallel to `cells` (infinite: never); empty otherwise.
  std::vector<std::vector<double>> robots;
  bool empty() const { return cells.empty(); }
};

}  // namespace covsim
