#pragma once
// Settings of the paper's coverage controller (Algorithms 1 and 2), with the defaults a
// scenario file gets when it leaves them out.
#include <optional>
#include <string>

#include "core/sim_time.hpp"

namespace covsim {

enum class LoopMode {
  classic,   // a robot runs loop 1 again once it has reached its real target (or settled)
  periodic,  // loop 1 runs every loop1_period, whatever the robots are doing
};

struct CoverageConfig {
  LoopMode mode = LoopMode::classic;
  SimTime loop2_period = SimTime::from_ns(100'000'000);    // 0.1 s: one motion step
  SimTime loop1_period = SimTime::from_ns(1'000'000'000);  // periodic mode only
  double max_speed = 0.1;                                  // m/s
  double sensor_range = INFINITY;                          // 0, finite or infinite
  std::string planner = "tangent_bug";
  // Convergence: every robot settled at its real target (within position_tolerance) and
  // every virtual generator within virtual_tolerance of its virtual target. Unset: 1e-3
  // of the diameter of Ω's bounding box.
  std::optional<double> position_tolerance;
  std::optional<double> virtual_tolerance;
  SimTime max_time = SimTime::from_ns(600'000'000'000);   // 600 s
  SimTime sample_period = SimTime::from_ns(500'000'000);  // metrics every 0.5 s
};

}  // namespace covsim
