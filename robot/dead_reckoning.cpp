#include "robot/dead_reckoning.hpp"

#include <cmath>

#include "robot/event_classes.hpp"

namespace covsim {

ParamSpec drift_parameter(double default_value) {
  return ParamSpec::number("drift", "m^½",
                           "the odometry's standard deviation on each axis per √m travelled")
      .non_negative()
      .at_most(1.0)
      .defaults_to(default_value);
}

DeadReckoning::DeadReckoning(const LocalizationContext& context, DeadReckoningConfig config)
    : kernel_(context.kernel), position_(context.position), config_(config) {
  for (std::uint32_t i = 0; i < context.starts.size(); ++i) {
    robots_.push_back(Tracked{context.starts[i],
                              Vec2{},
                              {},
                              kernel_.stream(i, "localization-fix"),
                              kernel_.stream(i, "localization-drift"),
                              kernel_.stream(i, "localization-loss"),
                              context.starts[i]});
  }
  if (config_.rate)
    frame_kind_ = kernel_.add_kind("tracking_frame", [this](Kernel&, const Event&) { frame(); });
}

void DeadReckoning::start(SimTime t0) {
  // A frame sees the motion steps of its instant (it comes after loop 2 in that instant).
  if (config_.rate)
    kernel_.schedule_periodic(Period::from_rate(*config_.rate), t0, frame_kind_, event_class::world,
                              event_class::broadcast);
}

void DeadReckoning::frame() {
  const SimTime delivered = kernel_.now() + config_.latency;
  for (std::uint32_t i = 0; i < robots_.size(); ++i) {
    Tracked& t = robots_[i];
    if (config_.loss > 0.0 && t.loss_rng.bernoulli(config_.loss)) continue;  // marker not found
    Vec2 fix = position_(i);
    if (config_.noise > 0.0)
      fix = fix + Vec2{t.fix_rng.normal(0.0, config_.noise), t.fix_rng.normal(0.0, config_.noise)};
    t.pending.push_back(Fix{delivered, fix, t.odometry});
  }
}

void DeadReckoning::moved(std::uint32_t i, Vec2 d) {
  Tracked& t = robots_[i];
  const double length = norm(d);
  if (length == 0.0) return;
  if (config_.drift == 0.0) {
    // Without drift the odometry is the position itself (and sums of displacements would
    // only round away from it).
    t.odometry = position_(i);
    return;
  }
  Vec2 e = d;
  if (config_.drift > 0.0) {
    const double sigma = config_.drift * std::sqrt(length);
    e = e + Vec2{t.drift_rng.normal(0.0, sigma), t.drift_rng.normal(0.0, sigma)};
  }
  t.odometry = t.odometry + e;
}

void DeadReckoning::deliver(std::uint32_t i) const {
  Tracked& t = robots_[i];
  // The latest fix delivered by now: where the robot was at its capture (compensated) or is now.
  while (!t.pending.empty() && t.pending.front().delivered <= kernel_.now()) {
    const Fix& f = t.pending.front();
    t.correction = f.position - (config_.compensated ? f.odometry : t.odometry);
    t.last_fix = f.position;
    t.pending.pop_front();
    ++fixes_;
  }
}

Vec2 DeadReckoning::odometry(std::uint32_t i) const {
  if (config_.odometry) return robots_[i].odometry;
  deliver(i);
  return robots_[i].last_fix;
}

Vec2 DeadReckoning::estimate(std::uint32_t i) {
  deliver(i);
  const Tracked& t = robots_[i];
  return config_.odometry ? t.odometry + t.correction : t.last_fix;
}

double DeadReckoning::odometry_jitter(double step) const {
  // Without odometry the planner's frame is the last fix: it jumps by a fix's noise.
  if (!config_.odometry) return std::sqrt(2.0) * config_.noise;
  return config_.drift * std::sqrt(step);
}

std::optional<double> DeadReckoning::estimate_sigma(double speed) const {
  // Between fixes the odometry drifts over the way driven in a frame period; a fix applied
  // uncompensated lags by the way driven over the latency.
  if (!config_.rate) {
    if (config_.drift > 0.0) return std::nullopt;
    return 0.0;
  }
  if (!config_.odometry)  // the last fix: up to a frame period and the latency old
    return config_.noise + speed * (config_.latency.seconds() + 1.0 / *config_.rate);
  const double between = config_.drift * config_.drift * speed / *config_.rate;
  const double lag = config_.compensated ? 0.0 : speed * config_.latency.seconds();
  return std::sqrt(config_.noise * config_.noise + between) + lag;
}

double DeadReckoning::estimate_jitter(double step) const {
  // A fix replaces one error by another, independent one; odometry adds drift over the step.
  if (!config_.odometry) return std::sqrt(2.0) * config_.noise;
  const double fix = config_.rate ? 2.0 * config_.noise * config_.noise : 0.0;
  return std::sqrt(fix + config_.drift * config_.drift * step);
}

}  // namespace covsim
