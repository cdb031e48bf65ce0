#pragma once
// What each robot's range sensor gives its planner. Exact by default: a fresh reading at
// every loop-2 step. With a period, "sense" events refresh each robot's reading and the
// planner gets the latest one; readings may carry Gaussian range noise and be lost (dropout,
// the planner keeping the last one), from per-robot streams. Contacts and the robot's own
// position are always current; the reading's origin says where its range part was taken.
#include <optional>
#include <vector>

#include "core/kernel.hpp"
#include "planners/sensor_reading.hpp"

namespace covsim {

struct SensorConfig {
  double range = INFINITY;  // 0, finite or infinite
  std::optional<SimTime> period;
  double noise_sigma = 0.0;
  double dropout = 0.0;
  bool exact() const { return !period && noise_sigma == 0.0 && dropout == 0.0; }
};

class SensorModel {
 public:
  // space(i): where robot i senses, Ω or its part of Ω shrunk by its radius (what its range
  // sensor measures, grown by its own body).
  SensorModel(Kernel& kernel, std::function<const Environment&(std::uint32_t)> space,
              SensorConfig config, std::size_t robots,
              const std::function<Vec2(std::uint32_t)>& position);
  // Every robot senses Ω.
  SensorModel(Kernel& kernel, const Environment& env, SensorConfig config, std::size_t robots,
              const std::function<Vec2(std::uint32_t)>& position)
      : SensorModel(
            kernel, [&env](std::uint32_t) -> const Environment& { return env; }, config, robots,
            position) {}
  // Schedules the periodic readings, if any.
  void start(SimTime t0);
  // What robot i's planner gets at a loop-2 step, the robot standing at `position`.
  SensorReading reading(std::uint32_t i, Vec2 position);

 private:
  void take_reading(std::uint32_t i, Vec2 position);

  Kernel& kernel_;
  std::function<const Environment&(std::uint32_t)> space_;
  SensorConfig config_;
  std::function<Vec2(std::uint32_t)> position_;
  EventKind sense_kind_ = 0;
  std::vector<RandomStream> noise_rng_, dropout_rng_;
  std::vector<SensorReading> last_;
  std::vector<bool> has_reading_;
};

}  // namespace covsim
