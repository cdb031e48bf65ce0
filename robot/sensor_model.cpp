#include "robot/sensor_model.hpp"

#include "robot/event_classes.hpp"

namespace covsim {

SensorModel::SensorModel(Kernel& kernel, std::function<const Environment&(std::uint32_t)> space,
                         SensorConfig config, std::size_t robots,
                         const std::function<Vec2(std::uint32_t)>& position)
    : kernel_(kernel), space_(std::move(space)), config_(config), position_(position) {
  if (config_.exact()) return;
  for (std::uint32_t i = 0; i < robots; ++i) {
    noise_rng_.push_back(kernel_.stream(i, "sensor-noise"));
    dropout_rng_.push_back(kernel_.stream(i, "sensor-dropout"));
  }
  last_.resize(robots);
  has_reading_.assign(robots, false);
  if (config_.period) {
    sense_kind_ = kernel_.add_kind("sense", [this](Kernel&, const Event& ev) {
      take_reading(ev.entity, position_(ev.entity));
    });
  }
}

void SensorModel::start(SimTime t0) {
  if (!config_.period) return;
  for (std::uint32_t i = 0; i < last_.size(); ++i) {
    kernel_.schedule_periodic(Period::from_ns(config_.period->ns()), t0, sense_kind_, i,
                              event_class::sense);
  }
}

void SensorModel::take_reading(std::uint32_t i, Vec2 position) {
  // A lost reading leaves the planner with the last one (the first is never lost).
  if (config_.dropout > 0.0 && has_reading_[i] && dropout_rng_[i].bernoulli(config_.dropout))
    return;
  const Environment& env = space_(i);
  last_[i] = sense(env, position, config_.range);
  if (config_.noise_sigma > 0.0)
    add_range_noise(last_[i], noise_rng_[i], config_.noise_sigma, env.tolerance());
  has_reading_[i] = true;
}

SensorReading SensorModel::reading(std::uint32_t i, Vec2 position) {
  if (config_.exact()) return sense(space_(i), position, config_.range);
  // The latest range reading (taken at its origin), with the robot's own position and its
  // current contacts.
  if (!config_.period) take_reading(i, position);
  SensorReading now = last_[i];
  now.position = position;
  now.contacts = contacts_at(space_(i), position);
  return now;
}

}  // namespace covsim
