#include "robot/coverage_controller.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/geometry/delaunay.hpp"
#include "planners/planner_registry.hpp"

namespace covsim {

namespace {
// Same-time order within a tick: targets first, then motion, then samples, then the check.
constexpr Priority kLoop1 = 0, kSense = 1, kLoop2 = 2, kBroadcast = 3, kDeliver = 4, kSample = 5,
                   kCheck = 6;
constexpr EntityId kWorld = UINT32_MAX;  // the entity of events that concern every robot
}  // namespace

std::string_view to_string(ControllerKind k) {
  switch (k) {
    case ControllerKind::virtual_generators:
      return "virtual_generators";
    case ControllerKind::euclidean_lloyd:
      return "euclidean_lloyd";
    case ControllerKind::geodesic_lloyd:
      return "geodesic_lloyd";
  }
  return "unknown";
}

CoverageController::CoverageController(Kernel& kernel, const Environment& env,
                                       const Density& density, const std::vector<Vec2>& starts,
                                       CoverageConfig config, const PlannerMaker& make_planner)
    : kernel_(kernel),
      env_(env),
      integrator_(env, density),
      config_(std::move(config)),
      planners_(planner_source(config_.planner,
                               PlannerContext{env, SensorSpec{config_.sensor_noise_sigma}})) {
  position_tol_ = config_.position_tolerance.value_or(1e-3 * env.diameter());
  virtual_tol_ = config_.virtual_tolerance.value_or(1e-3 * env.diameter());
  step_ = config_.max_speed * config_.loop2_period.seconds();
  for (std::uint32_t i = 0; i < starts.size(); ++i) {
    Robot r;
    r.id = i;
    r.position = r.virtual_generator = r.virtual_target = r.real_target = r.goal = r.assigned =
        starts[i];
    r.planner = make_planner ? make_planner(i) : planners_();
    robots_.push_back(std::move(r));
  }
  if (config_.controller.kind == ControllerKind::geodesic_lloyd) {
    graph_ = std::make_unique<VisibilityGraph>(env);
    lattice_points_ = std::make_unique<GeodesicLattice>(
        *graph_, density, config_.controller.resolution.value_or(env.diameter() / 100.0));
  }
  loop1_kind_ = kernel_.add_kind("loop1", [this](Kernel&, const Event& ev) { loop1(ev.entity); });
  loop2_kind_ =
      kernel_.add_kind("loop2", [this](Kernel& k, const Event& ev) { loop2(k, ev.entity); });
  sample_kind_ = kernel_.add_kind("sample", [this](Kernel& k, const Event&) {
    if (observer_ != nullptr) observer_->on_sample(k.now(), *this);
  });
  check_kind_ = kernel_.add_kind("check", [this](Kernel& k, const Event&) { check(k); });

  if (!ideal_sensor()) {
    for (std::uint32_t i = 0; i < robots_.size(); ++i) {
      noise_rng_.push_back(kernel_.stream(i, "sensor-noise"));
      dropout_rng_.push_back(kernel_.stream(i, "sensor-dropout"));
    }
    if (config_.sensor_period) {
      sense_kind_ =
          kernel_.add_kind("sense", [this](Kernel&, const Event& ev) { take_reading(ev.entity); });
    }
  }
  if (!config_.network.channel.is_ideal()) {
    channel_ = std::make_unique<Channel>(config_.network.channel, kernel_.seed(), env);
    tables_.resize(robots_.size());
    next_seq_.assign(robots_.size(), 0);
    broadcast_kind_ = kernel_.add_kind(
        "broadcast", [this](Kernel& k, const Event& ev) { broadcast(k, ev.entity); });
    deliver_kind_ = kernel_.add_kind("deliver", [this](Kernel&, const Event& ev) {
      const auto slot = static_cast<std::uint32_t>(ev.payload);
      tables_[ev.entity].update(in_flight_[slot]);
      free_slots_.push_back(slot);
    });
    // Points of Ω on a lattice, for estimating where the robots' own cells disagree.
    const Box& b = env.bounds();
    const int m = 64;
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) {
        const Vec2 p = b.lo + Vec2{(i + 0.5) * b.size().x / m, (j + 0.5) * b.size().y / m};
        if (env.contains(p)) lattice_.push_back(p);
      }
    }
    lattice_weight_ = lattice_.empty() ? 0.0 : env.area() / static_cast<double>(lattice_.size());
  }
}

void CoverageController::start() {
  const SimTime t0 = t0_ = kernel_.now();
  // Decentralized, the first loop 1 waits for the first round of broadcasts.
  const SimTime first = channel_ ? t0 + config_.network.acquire_time() : t0;
  acquired_.assign(robots_.size(), channel_ == nullptr);
  for (std::uint32_t i = 0; i < robots_.size(); ++i) {
    if (config_.mode == LoopMode::classic) {
      kernel_.schedule_at(first, loop1_kind_, i, kLoop1);
    } else {
      kernel_.schedule_periodic(Period::from_ns(config_.loop1_period.ns()), first, loop1_kind_, i,
                                kLoop1);
    }
    // A loop-2 step at time t is the motion over (t - period, t]: the first ends at t0 + period.
    kernel_.schedule_periodic(Period::from_ns(config_.loop2_period.ns()), t0 + config_.loop2_period,
                              loop2_kind_, i, kLoop2);
  }
  if (config_.sensor_period) {
    for (std::uint32_t i = 0; i < robots_.size(); ++i) {
      kernel_.schedule_periodic(Period::from_ns(config_.sensor_period->ns()), t0, sense_kind_, i,
                                kSense);
    }
  }
  if (channel_) {
    const Period period = Period::from_ns(config_.network.broadcast_period.ns());
    for (std::uint32_t i = 0; i < robots_.size(); ++i) {
      SimTime phase = t0;
      if (config_.network.random_phase) {
        phase += SimTime::from_seconds(
            kernel_.stream(i, "broadcast-phase").uniform(0.0, period.seconds()));
      }
      kernel_.schedule_periodic(period, phase, broadcast_kind_, i, kBroadcast);
    }
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

// Robots (or virtual generators) at the same place share one cell: the first gets it. H
// does not depend on how a shared cell is split.
const VoronoiPartition& CoverageController::virtual_partition() {
  if (!virtual_partition_) {
    virtual_partition_ = std::make_unique<VoronoiPartition>(integrator_, virtual_generators(),
                                                            VoronoiPartition::Coincident::split);
  }
  return *virtual_partition_;
}

const VoronoiPartition& CoverageController::real_partition() {
  if (!real_partition_) {
    real_partition_ = std::make_unique<VoronoiPartition>(integrator_, positions(),
                                                         VoronoiPartition::Coincident::split);
  }
  return *real_partition_;
}

const GeodesicPartition& CoverageController::geodesic_partition() {
  if (!geodesic_partition_)
    geodesic_partition_ = std::make_unique<GeodesicPartition>(*lattice_points_, positions());
  return *geodesic_partition_;
}

CoverageController::Known CoverageController::known_generators(std::uint32_t i,
                                                               bool positions) const {
  Known known;
  const Vec2 own = positions ? robots_[i].position : robots_[i].virtual_generator;
  bool placed = false;
  for (const auto& [sender, m] : tables_[i].entries()) {  // by sender id
    if (!placed && sender > i) {
      known.self = known.points.size();
      known.points.push_back(own);
      placed = true;
    }
    known.points.push_back(positions ? m.position : m.virtual_generator);
  }
  if (!placed) {
    known.self = known.points.size();
    known.points.push_back(own);
  }
  return known;
}

bool CoverageController::acquiring(std::uint32_t i) {
  if (acquired_[i]) return false;
  const SimTime now = kernel_.now();
  if (now < t0_ + config_.network.acquire_time()) return true;
  // Nobody heard yet: wait for a first message, up to the deadline.
  if (tables_[i].size() == 0 && now < t0_ + config_.network.acquire_deadline()) return true;
  acquired_[i] = true;
  return false;
}

CellSummary CoverageController::own_cell(std::uint32_t i, ConvexPolygon* cell) {
  const Vec2 g = robots_[i].virtual_generator;
  if (!channel_) {
    const VoronoiPartition& p = virtual_partition();
    if (cell != nullptr) cell->assign(p.cell(i).begin(), p.cell(i).end());
    return p.summary(i);
  }
  // Decentralized: the cell among the generators robot i has heard of, computed as the
  // centralized partition computes it.
  const Known known = known_generators(i, false);
  ConvexPolygon local;
  voronoi_cell(integrator_, known.points, known.self, local);
  const CellSummary s = summarize(integrator_.integrate(local, g), g);
  if (cell != nullptr) *cell = std::move(local);
  return s;
}

bool CoverageController::ideal_sensor() const {
  return !config_.sensor_period && config_.sensor_noise_sigma == 0.0 &&
         config_.sensor_dropout == 0.0;
}

void CoverageController::take_reading(std::uint32_t i) {
  Robot& r = robots_[i];
  // A lost reading leaves the planner with the last one (the first is never lost).
  if (config_.sensor_dropout > 0.0 && r.has_reading &&
      dropout_rng_[i].bernoulli(config_.sensor_dropout))
    return;
  r.reading = sense(env_, r.position, config_.sensor_range);
  if (config_.sensor_noise_sigma > 0.0) {
    add_range_noise(r.reading, noise_rng_[i], config_.sensor_noise_sigma, env_.tolerance());
  }
  r.has_reading = true;
}

void CoverageController::broadcast(Kernel& k, std::uint32_t i) {
  const Robot& r = robots_[i];
  const StateMessage m{i, next_seq_[i]++, k.now(), r.virtual_generator, r.position};
  for (std::uint32_t j = 0; j < robots_.size(); ++j) {
    if (j == i) continue;
    ++totals_.sent;
    const Channel::Transmission t = channel_->transmit(i, j, r.position, robots_[j].position);
    if (t.outcome == Channel::Outcome::lost) ++totals_.lost;
    if (t.outcome == Channel::Outcome::out_of_range || t.outcome == Channel::Outcome::blocked)
      ++totals_.unreachable;
    if (t.outcome != Channel::Outcome::delivered) continue;
    ++totals_.delivered;
    std::uint32_t slot;
    if (!free_slots_.empty()) {
      slot = free_slots_.back();
      free_slots_.pop_back();
      in_flight_[slot] = m;
    } else {
      slot = static_cast<std::uint32_t>(in_flight_.size());
      in_flight_.push_back(m);
    }
    k.schedule_in(t.delay, deliver_kind_, j, kDeliver, slot);
  }
}

NetworkSample CoverageController::network_sample() {
  NetworkSample s;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::uint32_t a = 0; a < robots_.size(); ++a) {
    for (std::uint32_t b = a + 1; b < robots_.size(); ++b) {
      if (!channel_ || channel_->in_reach(robots_[a].position, robots_[b].position))
        edges.emplace_back(a, b);
    }
  }
  s.graph = comm_graph_metrics(robots_.size(), edges);
  if (!channel_) return s;  // every robot knows everything at once
  double sum = 0.0;
  std::size_t count = 0;
  // Entries past the staleness limit are as good as gone (loop 1 drops them before use).
  const double limit = config_.network.staleness ? config_.network.staleness->seconds() : INFINITY;
  for (const NeighborTable& t : tables_) {
    for (double age : t.ages(kernel_.now())) {
      if (age > limit) continue;
      sum += age;
      ++count;
      s.info_age_max = std::max(s.info_age_max, age);
    }
  }
  s.info_age_mean = count > 0 ? sum / static_cast<double>(count) : 0.0;
  std::vector<ConvexPolygon> cells(robots_.size());
  for (std::uint32_t i = 0; i < robots_.size(); ++i)
    own_cell(i, &cells[i]);
  for (Vec2 p : lattice_) {
    int owners = 0;
    for (const ConvexPolygon& c : cells) {
      bool in = c.size() >= 3;
      for (std::size_t e = 0; e < c.size() && in; ++e)
        in = cross(c[(e + 1) % c.size()] - c[e], p - c[e]) >= 0.0;
      owners += in ? 1 : 0;
    }
    if (owners == 0) s.area_claimed_by_none += lattice_weight_;
    if (owners > 1) s.area_claimed_by_several += lattice_weight_;
  }
  return s;
}

void CoverageController::loop1(std::uint32_t i) {
  if (channel_ && acquiring(i)) return;
  // Algorithm 1, lines 3-5: the cell of the virtual generator among those the robot knows
  // of, and its centroid.
  if (channel_ && config_.network.staleness)
    tables_[i].drop_stale(kernel_.now(), *config_.network.staleness);
  const bool paper = config_.controller.kind == ControllerKind::virtual_generators;
  Robot& r = robots_[i];
  r.virtual_target = paper ? own_cell(i).centroid : baseline_target(i);
  // Algorithm 2, lines 2-4: an obstacle boundary Voronoi region projects its target.
  r.projected = !env_.contains(r.virtual_target);
  r.real_target = r.projected ? env_.closest_point(r.virtual_target) : r.virtual_target;
  // At its real target: for a projected target, at a closest point of Ω to the virtual one
  // (when several are equally close, the planner's is as good as the controller's).
  const bool at_target = r.projected
                             ? std::fabs(distance(r.position, r.virtual_target) -
                                         distance(r.real_target, r.virtual_target)) <= position_tol_
                             : distance(r.real_target, r.position) <= position_tol_;
  r.stable = is_settled(r.status) && at_target &&
             (!paper || distance(r.virtual_target, r.virtual_generator) <= virtual_tol_);
  if (r.stable) return;
  // Only a target that moved (by more than the position tolerance) restarts the planner: a
  // goal it reached, found unreachable or gave up on is never handed to it again (it would
  // only do the same again), and periodic updates cannot keep restarting a robot on its way
  // round an obstacle.
  if (distance(r.virtual_target, r.assigned) > position_tol_) {
    set_goal(r, r.virtual_target);
    r.assigned = r.virtual_target;
  }
}

void CoverageController::set_goal(Robot& r, Vec2 goal) {
  r.planner->set_goal(goal);
  r.goal = goal;
  r.status = PlanStatus::moving;
}

Vec2 CoverageController::baseline_target(std::uint32_t i) {
  const bool geodesic = config_.controller.kind == ControllerKind::geodesic_lloyd;
  if (geodesic) {
    const Vec2 p = robots_[i].position;
    if (!channel_) return p + config_.controller.gain * (geodesic_partition().cell(i).target - p);
    const Known known = known_generators(i, true);
    return p + config_.controller.gain *
                   (GeodesicPartition(*lattice_points_, known.points).cell(known.self).target - p);
  }
  if (!channel_) return real_partition().summary(i).centroid;
  const Known known = known_generators(i, true);
  ConvexPolygon cell;
  voronoi_cell(integrator_, known.points, known.self, cell);
  return summarize(integrator_.integrate(cell, known.points[known.self]), known.points[known.self])
      .centroid;
}

void CoverageController::loop2(Kernel& k, std::uint32_t i) {
  Robot& r = robots_[i];
  if (!is_settled(r.status)) {
    // Algorithm 2, line 5: a planner step toward the real target, in the real world.
    PlanStep s;
    SensorReading now;
    if (ideal_sensor()) {
      now = sense(env_, r.position, config_.sensor_range);
    } else {
      // The latest range reading, with the robot's own position and its current contacts.
      if (!config_.sensor_period) take_reading(i);
      now = r.reading;
      now.position = r.position;
      now.contacts = contacts_at(env_, r.position);
    }
    const auto started = std::chrono::steady_clock::now();
    s = r.planner->step(now, step_);
    planner_totals_.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    ++planner_totals_.steps;
    const Vec2 next = env_.advance(r.position, s.next);
    if (!env_.segment_inside(r.position, next)) {
      throw std::logic_error(
          fmt::format("robot {} left the environment at t={} s: ({}, {}) -> ({}, {})", i,
                      k.now().seconds(), r.position.x, r.position.y, next.x, next.y));
    }
    r.path_length += distance(r.position, next);
    if (!(next == r.position)) {
      real_partition_.reset();
      geodesic_partition_.reset();
    }
    r.position = next;
    r.status = s.status;
    r.stable = false;
    if (s.status == PlanStatus::projected && env_.contains(r.goal)) {
      failure_ = PlannerFailure{i, k.now(), r.goal, r.position};
      k.stop();
      return;
    }
    // A planner that gives up on a target outside Ω: the target is unreachable, so the
    // robot goes to its projection instead.
    if (r.status == PlanStatus::stalled && r.projected && !(r.goal == r.real_target)) {
      r.stalled_time += config_.loop2_period.seconds();
      set_goal(r, r.real_target);
    }
  }
  if (r.projected) ++r.target_outside_steps;
  if (r.status == PlanStatus::stalled) r.stalled_time += config_.loop2_period.seconds();
  if (config_.controller.kind == ControllerKind::virtual_generators) {
    // Line 6: the virtual generator steps toward the virtual target as if Ω were convex.
    const Vec2 d = r.virtual_target - r.virtual_generator;
    const double dn = norm(d);
    if (dn > 0.0) {
      r.virtual_generator = dn <= step_ ? r.virtual_target : r.virtual_generator + (step_ / dn) * d;
      virtual_partition_.reset();
    }
  } else if (!(r.virtual_generator == r.position)) {
    r.virtual_generator = r.position;  // the baselines have no virtual generators
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
  const bool paper = config_.controller.kind == ControllerKind::virtual_generators;
  bool all_stable = true, all_resting = true;
  for (const Robot& r : robots_) {
    all_stable = all_stable && r.stable;
    // Stuck: stalled short of a target that has not moved, with (for the paper's
    // controller) the virtual generator at rest on its target.
    const bool stuck = r.status == PlanStatus::stalled &&
                       distance(r.virtual_target, r.assigned) <= position_tol_ &&
                       (!paper || distance(r.virtual_target, r.virtual_generator) <= virtual_tol_);
    all_resting = all_resting && (r.stable || stuck);
  }
  if (all_stable) {
    converged_ = true;
    k.stop();
  } else if (all_resting) {
    stuck_ = true;
    k.stop();
  }
}

}  // namespace covsim
