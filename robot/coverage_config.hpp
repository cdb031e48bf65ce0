#pragma once
// Settings of the paper's coverage controller (Algorithms 1 and 2), with the defaults a
// scenario file gets when it leaves them out.
#include <optional>
#include <string>

#include "core/sim_time.hpp"
#include "net/channel.hpp"

namespace covsim {

enum class LoopMode {
  classic,   // a robot runs loop 1 again once it has reached its real target (or settled)
  periodic,  // loop 1 runs every loop1_period, whatever the robots are doing
};

// Neighbour messages. With the ideal channel (the default) every robot knows every other
// robot's state at once, which is the centralized controller, and no message is simulated.
struct NetworkConfig {
  ChannelConfig channel;
  SimTime broadcast_period = SimTime::from_ns(100'000'000);  // 0.1 s
  bool random_phase = false;         // each robot's first broadcast at a random offset
  std::optional<SimTime> staleness;  // entries older than this are dropped; unset: never
};

struct CoverageConfig {
  LoopMode mode = LoopMode::classic;
  SimTime loop2_period = SimTime::from_ns(100'000'000);    // 0.1 s: one motion step
  SimTime loop1_period = SimTime::from_ns(1'000'000'000);  // periodic mode only
  double max_speed = 0.1;                                  // m/s
  double sensor_range = INFINITY;                          // 0, finite or infinite
  // The range sensor is read every sensor_period (unset: at every loop-2 step); a reading
  // is lost with probability sensor_dropout (the planner keeps the last one) and its ranges
  // carry Gaussian noise of sensor_noise_sigma metres. Contact sensing is always current.
  std::optional<SimTime> sensor_period;
  double sensor_noise_sigma = 0.0;
  double sensor_dropout = 0.0;
  std::string planner = "tangent_bug";
  // Convergence: every robot settled at its real target (within position_tolerance) and
  // every virtual generator within virtual_tolerance of its virtual target. Unset: 1e-3
  // of the diameter of Ω's bounding box.
  std::optional<double> position_tolerance;
  std::optional<double> virtual_tolerance;
  SimTime max_time = SimTime::from_ns(600'000'000'000);   // 600 s
  SimTime sample_period = SimTime::from_ns(500'000'000);  // metrics every 0.5 s
  NetworkConfig network;
};

}  // namespace covsim
