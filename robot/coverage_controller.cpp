#include "robot/coverage_controller.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "planners/planner_factory.hpp"

namespace covsim {

namespace {
// Same-time order within a tick: targets first, then motion, then samples, then the check.
constexpr Priority kLoop1 = 0, kLoop2 = 1, kSample = 2, kCheck = 3;
constexpr EntityId kWorld = UINT32_MAX;  // the entity of events that concern every robot
}  // namespace

CoverageController::CoverageController(Kernel& kernel, const Environment& env,
                                       const Density& density, const std::vector<Vec2>& starts,
                                       CoverageConfig config)
    : kernel_(kernel), env_(env), integrator_(env, density), config_(std::move(config)) {
  position_tol_ = config_.position_tolerance.value_or(1e-3 * env.diameter());
  virtual_tol_ = config_.virtual_tolerance.value_or(1e-3 * env.diameter());
  step_ = config_.max_speed * config_.loop2_period.seconds();
  for (std::uint32_t i = 0; i < starts.size(); ++i) {
    Robot r;
    r.id = i;
    r.position = r.virtual_generator = r.virtual_target = r.real_target = r.goal = starts[i];
    r.planner = make_planner(config_.planner, env);
    robots_.push_back(std::move(r));
  }
  loop1_kind_ = kernel_.add_kind("loop1", [this](Kernel&, const Event& ev) { loop1(ev.entity); });
  loop2_kind_ =
      kernel_.add_kind("loop2", [this](Kernel& k, const Event& ev) { loop2(k, ev.entity); });
  sample_kind_ = kernel_.add_kind("sample", [this](Kernel& k, const Event&) {
    if (observer_ != nullptr) observer_->on_sample(k.now(), *this);
  });
  check_kind_ = kernel_.add_kind("check", [this](Kernel& k, const Event&) { check(k); });
}

void CoverageController::start() {
  const SimTime t0 = kernel_.now();
  for (std::uint32_t i = 0; i < robots_.size(); ++i) {
    if (config_.mode == LoopMode::classic) {
      kernel_.schedule_at(t0, loop1_kind_, i, kLoop1);
    } else {
      kernel_.schedule_periodic(Period::from_ns(config_.loop1_period.ns()), t0, loop1_kind_, i,
                                kLoop1);
    }
    // A loop-2 step at time t is the motion over (t - period, t]: the first ends at t0 + period.
    kernel_.schedule_periodic(Period::from_ns(config_.loop2_period.ns()), t0 + config_.loop2_period,
                              loop2_kind_, i, kLoop2);
  }
  kernel_.schedule_periodic(Period::from_ns(config_.sample_period.ns()), t0, sample_kind_, kWorld,
                            kSample);
  kernel_.schedule_periodic(Period::from_ns(config_.loop2_period.ns()), t0 + config_.loop2_period,
                            check_kind_, kWorld, kCheck);
}

std::vector<Vec2> CoverageController::positions() const {
  std::vector<Vec2> out;
  for (const Robot& r : robots_)
    out.push_back(r.position);
  return out;
}

std::vector<Vec2> CoverageController::virtual_generators() const {
  std::vector<Vec2> out;
  for (const Robot& r : robots_)
    out.push_back(r.virtual_generator);
  return out;
}

const VoronoiPartition& CoverageController::virtual_partition() {
  if (!virtual_partition_)
    virtual_partition_ = std::make_unique<VoronoiPartition>(integrator_, virtual_generators());
  return *virtual_partition_;
}

VoronoiPartition CoverageController::real_partition() const {
  // Robots at the same place (two projections onto one boundary point) share one cell:
  // the partition is of the distinct positions, and H does not depend on the split.
  std::vector<Vec2> distinct;
  for (const Robot& r : robots_) {
    if (std::find(distinct.begin(), distinct.end(), r.position) == distinct.end())
      distinct.push_back(r.position);
  }
  return VoronoiPartition(integrator_, distinct);
}

void CoverageController::loop1(std::uint32_t i) {
  // Algorithm 1, lines 3-5: the cell of the virtual generator and its centroid.
  const CellSummary cell = virtual_partition().summary(i);
  Robot& r = robots_[i];
  r.virtual_target = cell.centroid;
  // Algorithm 2, lines 2-4: an obstacle boundary Voronoi region projects its target.
  r.projected = !env_.contains(r.virtual_target);
  r.real_target = r.projected ? env_.closest_point(r.virtual_target) : r.virtual_target;
  r.stable = is_settled(r.status) &&
             distance(r.virtual_target, r.virtual_generator) <= virtual_tol_ &&
             distance(r.real_target, r.position) <= position_tol_;
  // A target that moved less than the position tolerance does not restart the planner:
  // otherwise periodic updates could keep a robot from ever getting round an obstacle.
  if (!r.stable && (is_settled(r.status) || distance(r.virtual_target, r.goal) > position_tol_)) {
    r.planner->set_goal(r.virtual_target);
    r.goal = r.virtual_target;
    r.status = PlanStatus::moving;
  }
}

void CoverageController::loop2(Kernel& k, std::uint32_t i) {
  Robot& r = robots_[i];
  if (!is_settled(r.status)) {
    // Algorithm 2, line 5: a planner step toward the real target, in the real world.
    const PlanStep s = r.planner->step(sense(env_, r.position, config_.sensor_range), step_);
    const Vec2 next = env_.advance(r.position, s.next);
    if (!env_.segment_inside(r.position, next)) {
      throw std::logic_error(
          fmt::format("robot {} left the environment at t={} s: ({}, {}) -> ({}, {})", i,
                      k.now().seconds(), r.position.x, r.position.y, next.x, next.y));
    }
    r.path_length += distance(r.position, next);
    r.position = next;
    r.status = s.status;
    r.stable = false;
  }
  // Line 6: the virtual generator steps toward the virtual target as if Ω were convex.
  const Vec2 d = r.virtual_target - r.virtual_generator;
  const double dn = norm(d);
  if (dn > 0.0) {
    r.virtual_generator = dn <= step_ ? r.virtual_target : r.virtual_generator + (step_ / dn) * d;
    virtual_partition_.reset();
  }
  if (config_.mode == LoopMode::classic && is_settled(r.status)) {
    k.schedule_at(k.now() + config_.loop2_period, loop1_kind_, i, kLoop1);
  }
  if (observer_ != nullptr) observer_->on_motion(k.now(), r);
}

void CoverageController::check(Kernel& k) {
  for (const Robot& r : robots_) {
    k.fingerprint().fold_state(r.position.x);
    k.fingerprint().fold_state(r.position.y);
    k.fingerprint().fold_state(r.virtual_generator.x);
    k.fingerprint().fold_state(r.virtual_generator.y);
  }
  bool all_stable = true;
  for (const Robot& r : robots_)
    all_stable = all_stable && r.stable;
  if (all_stable) {
    converged_ = true;
    k.stop();
  }
}

}  // namespace covsim
