#pragma once
#include <stdexcept>

namespace covsim {

// Invalid geometric input: the message says which ring, vertex or edge and what is wrong.
struct GeometryError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

}  // namespace covsim
