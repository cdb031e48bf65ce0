#pragma once
// Shapes the geometry tests build environments from.
#include <vector>

#include "core/vec2.hpp"

namespace covsim::test {

// The axis-parallel rectangle [x0, x1] x [y0, y1], counter-clockwise.
inline std::vector<Vec2> square(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

}  // namespace covsim::test
