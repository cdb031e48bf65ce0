#pragma once
#include <stdexcept>
#include <string>

namespace covsim {

// Invalid geometric input: the message says which ring, vertex or edge and what is wrong;
// ring() says which ring (0 outer, h + 1 hole h) when one is at fault, so that callers
// reading a file can point at it.
class GeometryError : public std::invalid_argument {
 public:
  explicit GeometryError(const std::string& what, int ring = -1)
      : std::invalid_argument(what), ring_(ring) {}
  int ring() const { return ring_; }

 private:
  int ring_;
};

}  // namespace covsim
