#pragma once
// Times in the kernel tests are written as nanosecond counts.
#include <cstdint>

#include "core/sim_time.hpp"

namespace covsim::test {

inline SimTime ns(std::int64_t v) {
  return SimTime::from_ns(v);
}

}  // namespace covsim::test
