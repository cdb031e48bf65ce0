#include "core/sim_time.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace covsim {

SimTime SimTime::from_seconds(double seconds) {
  // 9.2e9 s is the int64 nanosecond limit; stay clear of it so rounding cannot overflow.
  if (!std::isfinite(seconds) || std::fabs(seconds) > 9.2e9) {
    throw std::invalid_argument("time of " + std::to_string(seconds) +
                                " s is not a finite value within ±9.2e9 s");
  }
  return SimTime(std::llround(seconds * 1e9));
}

}  // namespace covsim
