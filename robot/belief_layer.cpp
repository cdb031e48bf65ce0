#include "robot/belief_layer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "planners/planner_map.hpp"
#include "planners/planner_registry.hpp"
#include "robot/localization_registry.hpp"
#include "robot/mapping.hpp"

namespace covsim {

BeliefLayer::BeliefLayer(Kernel& kernel, const Environment& env, const Density& density,
                         const std::vector<Vec2>& starts, const CoverageConfig& config, double step,
                         double tolerance, std::function<Vec2(std::uint32_t)> position,
                         std::function<const Environment&(std::uint32_t)> free_space)
    : free_space_(std::move(free_space)), step_(step), tolerance_(tolerance) {
  localization_ =
      make_localization(config.localization, LocalizationContext{kernel, starts, position});
  sensing_ = SensorSpec{config.sensor.noise_sigma,
                        localization_ ? localization_->odometry_jitter(step_) : 0.0};
  const PlannerEntry* planner = planner_registry().find(config.planner.type);
  map_frame_ = localization_ && planner != nullptr && !planner->senses_only &&
               !plans_on_sensed_map(config.planner.params);
  if (map_frame_) {
    const std::optional<double> sigma = localization_->estimate_sigma(config.max_speed);
    if (!sigma)
      throw std::invalid_argument(
          fmt::format("{} localization beside the map planner {}: its error grows without bound",
                      config.localization.type, config.planner.type));
    inflation_ = config.inflation * *sigma;
    after_motion_ = starts;
  }
  if (config.mapping.unknown()) {
    mapping_ =
        std::make_unique<Mapping>(env, density, config.radius, config.sensor.range, config.mapping,
                                  starts.size(), config.network.channel.is_ideal());
    mapping_->set_clock([&kernel] { return kernel.now(); });
    // Uncertain readings (noisy ranges, placed by an estimate) make an occupancy grid.
    if (maps_on_grid(config)) {
      std::vector<RandomStream> streams;
      for (std::uint32_t i = 0; i < starts.size(); ++i)
        streams.push_back(kernel.stream(i, "mapping-noise"));
      const auto believed = [this, position](std::uint32_t i) {
        return localization_ ? localization_->estimate(i) : position(i);
      };
      mapping_->use_grid(
          config.sensor.noise_sigma, std::move(streams),
          [believed, position](std::uint32_t i) { return believed(i) - position(i); }, believed);
    }
  }
}

BeliefLayer::~BeliefLayer() = default;

void BeliefLayer::start(SimTime t0, const std::vector<Robot>& robots) {
  if (localization_) localization_->start(t0);
  if (mapping_) {
    for (const Robot& r : robots)
      mapping_->start(r.id, r.position, t0);
  }
}

const Environment& BeliefLayer::believed_free_space(const Robot& r) const {
  return mapping_ ? mapping_->free_space(r.id, r.position) : free_space_(r.id);
}

void BeliefLayer::tick(const Robot& r) {
  if (!localization_) return;
  const double error = distance(localization_->estimate(r.id), r.position);
  localization_error_sum_ += error;
  localization_error_max_ = std::max(localization_error_max_, error);
  ++localization_steps_;
}

void BeliefLayer::moving(const Robot& r, Vec2 p, double length, SimTime now) {
  if (mapping_) mapping_->moved(r.id, p, length, now);
}

void BeliefLayer::moved(const Robot& r, Vec2 d) {
  if (localization_) localization_->moved(r.id, d);
  if (map_frame_) after_motion_[r.id] = localization_->estimate(r.id);
}

bool BeliefLayer::estimate_jumped(const Robot& r) {
  if (!map_frame_) return false;
  const Vec2 e = localization_->estimate(r.id);
  const bool jumped = distance(e, after_motion_[r.id]) > within_reach();
  after_motion_[r.id] = e;
  return jumped;
}

void BeliefLayer::arrived(const Robot& r, PlanStatus status, SimTime now) {
  if (!mapping_ || !is_settled(status)) return;
  // Found unreachable a goal its map still places in free space: an obstacle not yet known
  // whole (the paper's Fig. 4 without a map).
  if (status == PlanStatus::projected && mapping_->free_space(r.id, r.position).contains(r.goal))
    ++discoveries_;
  mapping_->settled(r.id, r.position, now);
}

void BeliefLayer::believe(Knowledge& k, const CellIntegrator& integrator) {
  k.integrator = &integrator;
  if (k.shared == nullptr || !k.version) return;
  // Every generator known as it is now: one partition in that belief per change of the
  // generators or of the belief, shared by the robots that hold it (one shared map: all).
  BelievedPartition& b = believed_[k.kind == Generators::positions ? 1 : 0];
  if (!b.partition || b.integrator != &integrator || b.version != *k.version) {
    const auto split = VoronoiPartition::Coincident::split;
    // The next partition keeps the cells of the last that did not change: built beside it,
    // then put in its place.
    if (b.partition && b.integrator == &integrator) {
      VoronoiPartition next(integrator, k.points, split, std::move(*b.partition));
      b.partition.reset();
      b.partition.emplace(std::move(next));
    } else {
      b.partition.emplace(integrator, k.points, split);
    }
    b.integrator = &integrator;
    b.version = *k.version;
  }
  k.believed = &*b.partition;
}

Vec2 BeliefLayer::planner_position(const Robot& r) {
  if (map_frame_) return known_position(r);
  return localization_ ? localization_->odometry(r.id) : r.position;
}

Vec2 BeliefLayer::in_planner_frame(const Robot& r, Vec2 p) {
  if (!localization_ || map_frame_) return p;
  const Vec2 q = p - (localization_->estimate(r.id) - localization_->odometry(r.id));
  // A fix's noise must not make a goal the robot can reach one it cannot: moved by the fix's
  // error, a goal near a wall lands in it, and the planner walks round all of Ω to find it
  // unreachable (e-puck with 2 cm of tracking noise: a goal 2.8 cm from the grown wall, moved
  // 3.6 cm by a fix, sent its robot round the U). A goal in an obstacle on purpose (discover)
  // stays there.
  const Environment& space = free_space_(r.id);
  return space.contains(p) && !space.contains(q) ? space.closest_point(q) : q;
}

double BeliefLayer::reach(double sigma) const {
  return std::max(tolerance_, kReachDeviations * sigma);
}

double BeliefLayer::planner_reach() const {
  return map_frame_ ? within_reach() : reach(sensing_.position_sigma);
}

double BeliefLayer::within_reach() const {
  if (!localization_) return tolerance_;
  // A planner on the inflated map stops that far short of a goal on Ω's boundary.
  const double r = reach(localization_->estimate_jitter(step_));
  return map_frame_ ? std::max(r, inflation_ + tolerance_) : r;
}

Vec2 BeliefLayer::known_position(const Robot& r) {
  if (!localization_) return r.position;
  const Vec2 e = localization_->estimate(r.id);
  const Environment& space = free_space_(r.id);
  return space.contains(e) ? e : space.closest_point(e);
}

bool BeliefLayer::goal_unreachable(const Robot& r) const {
  const Environment& space = free_space_(r.id);
  if (!localization_) return !space.contains(r.goal);
  // On the inflated map: a goal within the inflation (and what the robot can tell) of the
  // boundary lies outside it.
  if (map_frame_)
    return !space.contains(r.planner_goal) ||
           space.boundary_distance(r.planner_goal) <= within_reach() + inflation_;
  // The planner's goal among the walls as it senses them; one nearer the boundary than the
  // robot can tell, or than its odometry has drifted while it walked, may have crossed it as
  // fixes and drift moved it.
  const Vec2 p = r.planner_goal - (localization_->odometry(r.id) - r.position);
  const double margin =
      std::max(within_reach(), reach(localization_->odometry_jitter(r.path_length)));
  return !space.contains(p) || space.boundary_distance(p) <= margin;
}

}  // namespace covsim
