#include "robot/coverage_controller.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "net/receiver_grid.hpp"
#include "planners/planner_map.hpp"
#include "planners/planner_registry.hpp"
#include "robot/collision_avoidance_registry.hpp"
#include "robot/component_error.hpp"
#include "robot/coverage_law_registry.hpp"
#include "robot/event_classes.hpp"
#include "robot/ideal_view.hpp"
#include "robot/kinematics_registry.hpp"
#include "robot/localization_registry.hpp"
#include "robot/mapping.hpp"
#include "robot/networked_view.hpp"
#include "robot/turn_then_drive.hpp"

namespace covsim {

CoverageController::CoverageController(Kernel& kernel, const Environment& env,
                                       const Density& density, const std::vector<Vec2>& starts,
                                       CoverageConfig config, const PlannerMaker& make_planner,
                                       const PlannerWrapper& wrap)
    : kernel_(kernel), env_(env), integrator_(env, density), config_(std::move(config)) {
  const double spacing = robot_spacing(env, starts.size());
  tol_ = Tolerances{config_.position_tolerance_in(env.diameter(), spacing),
                    config_.virtual_tolerance_in(env.diameter(), spacing)};
  step_ = config_.max_speed * config_.loop2_period.seconds();
  space_ = std::make_unique<ConfigurationSpace>(env, config_.radius);
  localization_ = make_localization(config_.localization,
                                    LocalizationContext{kernel_, starts, [this](std::uint32_t i) {
                                                          return robots_[i].position;
                                                        }});
  // What the planners are told of their sensing: its range noise, and how much the position
  // they plan from (the odometry) jumps.
  sensing_ = SensorSpec{config_.sensor.noise_sigma,
                        localization_ ? localization_->odometry_jitter(step_) : 0.0};
  // Each part of the free space has its planners' shared maps, built for the first robot in it
  // (centralized, with the ideal network, one sensed map for the robots' planners too).
  std::vector<std::optional<PlannerSource>> sources(space_->part_count());
  for (std::uint32_t i = 0; i < starts.size(); ++i) {
    std::size_t part = 0;
    if (config_.radius > 0.0) {
      const auto k = space_->part_of(starts[i]);
      if (!k)
        throw std::invalid_argument(fmt::format(
            "robot {} at ({}, {}): its body (radius {} m) overlaps an obstacle or leaves the "
            "environment",
            i, starts[i].x, starts[i].y, config_.radius));
      part = *k;
    }
    part_.push_back(part);
    Robot r;
    r.id = i;
    r.position = r.virtual_generator = r.virtual_target = r.real_target = r.goal = r.assigned =
        starts[i];
    if (make_planner) {
      r.planner = make_planner(i);
    } else {
      if (!sources[part])
        sources[part] = planner_source(
            config_.planner,
            PlannerContext{space_->part(part), sensing_, config_.network.channel.is_ideal()});
      r.planner = (*sources[part])();
    }
    if (wrap) r.planner = wrap(std::move(r.planner));
    robots_.push_back(std::move(r));
  }
  state_ = std::make_unique<GeneratorState>(integrator_, starts);
  law_ = make_coverage_law(config_.law, LawContext{env, density, integrator_});
  const bool ideal = config_.network.channel.is_ideal();
  if (config_.mapping.unknown())
    mapping_ = std::make_unique<Mapping>(env, density, config_.radius, config_.sensor.range,
                                         config_.mapping, starts.size(), ideal);
  if (mapping_) mapping_->set_clock([this] { return kernel_.now(); });
  // Decentralized, each robot's map planner also takes the walls of the readings it hears.
  if (mapping_ && !ideal && plans_on_sensed_map(config_.planner.params))
    mapping_->on_learn([this](std::uint32_t i, const Scan& s) { learn(i, s); });
  if (ideal) {
    view_ = std::make_unique<IdealView>(*state_);
  } else {
    view_ = std::make_unique<NetworkedView>(kernel_, env, config_.network, *state_, mapping_.get());
  }
  sensor_ = std::make_unique<SensorModel>(
      kernel_, [this](std::uint32_t i) -> const Environment& { return free_space(i); },
      config_.sensor, robots_.size(), [this](std::uint32_t i) { return robots_[i].position; });
  if (config_.radius > 0.0 && config_.avoidance.type != AvoidanceConfig{}.type)
    avoidance_ = make_collision_avoidance(config_.avoidance);
  kinematics_ = make_kinematics(config_.kinematics, KinematicsContext{config_.max_speed});
  if (avoidance_) {
    // The robots near one, for sensing and for the clearance of a motion, without testing
    // every robot.
    near_range_ = std::max(
        avoidance_->range(config_.radius, config_.max_speed, config_.loop2_period.seconds()),
        2.0 * config_.radius + step_);
    near_ = std::make_unique<ReceiverGrid>(near_range_, starts);
  }
  loop1_kind_ = kernel_.add_kind("loop1", [this](Kernel&, const Event& ev) { loop1(ev.entity); });
  loop2_kind_ =
      kernel_.add_kind("loop2", [this](Kernel& k, const Event& ev) { loop2(k, ev.entity); });
  sample_kind_ = kernel_.add_kind("sample", [this](Kernel& k, const Event&) {
    if (observer_ != nullptr) observer_->on_sample(k.now(), *this);
  });
  check_kind_ = kernel_.add_kind("check", [this](Kernel& k, const Event&) { check(k); });
}

CoverageController::~CoverageController() = default;

void CoverageController::start() {
  const SimTime t0 = kernel_.now();
  // Decentralized, the first loop 1 waits for the first round of broadcasts.
  const SimTime first = decentralized() ? t0 + config_.network.acquire_time() : t0;
  for (std::uint32_t i = 0; i < robots_.size(); ++i) {
    if (config_.mode == LoopMode::classic) {
      kernel_.schedule_at(first, loop1_kind_, i, event_class::loop1);
    } else {
      kernel_.schedule_periodic(Period::from_ns(config_.loop1_period.ns()), first, loop1_kind_, i,
                                event_class::loop1);
    }
    // A loop-2 step at time t is the motion over (t - period, t]: the first ends at t0 + period.
    kernel_.schedule_periodic(Period::from_ns(config_.loop2_period.ns()), t0 + config_.loop2_period,
                              loop2_kind_, i, event_class::loop2);
  }
  sensor_->start(t0);
  if (localization_) localization_->start(t0);
  if (mapping_) {
    for (const Robot& r : robots_)
      mapping_->start(r.id, r.position, t0);
  }
  view_->motion_clock(t0 + config_.loop2_period, config_.loop2_period);
  view_->start(t0);
  kernel_.schedule_periodic(Period::from_ns(config_.sample_period.ns()), t0, sample_kind_,
                            event_class::world, event_class::sample);
  kernel_.schedule_periodic(Period::from_ns(config_.loop2_period.ns()), t0 + config_.loop2_period,
                            check_kind_, event_class::world, event_class::check);
}

template <class F>
auto CoverageController::guarded(std::uint32_t i, std::string_view role, std::string_view name,
                                 F&& f) {
  try {
    return f();
  } catch (const ComponentError&) {
    throw;
  } catch (const std::exception& e) {
    std::throw_with_nested(ComponentError(
        fmt::format("robot {}'s {} \"{}\" at t = {} s", i, role, name, kernel_.now().seconds()),
        e.what()));
  }
}

void CoverageController::learn(std::uint32_t i, const Scan& scan) {
  std::vector<SensedPiece> walls;
  if (config_.radius == 0.0) {
    for (const VisiblePiece& p : scan.pieces)
      walls.push_back(SensedPiece{p.a, p.b});
  } else {
    // Bodies plan in Ω shrunk by their radius, whose walls the reading's walls determine: the
    // receiver takes them as seen from where the reading was taken (the whole reading's,
    // though a message may have carried part of it), when that lies in its part of the
    // free space.
    const auto k = space_->part_of(scan.origin);
    if (!k || *k != part_[i]) return;
    const SensorReading seen = sense(free_space(i), scan.origin, scan.range);
    walls = seen.visible().pieces;
  }
  Robot& r = robots_[i];
  guarded(i, "planner", r.planner->name(), [&] { r.planner->learn(walls); });
}

void CoverageController::loop1(std::uint32_t i) {
  if (!view_->ready(i)) return;
  // Algorithm 1, lines 3-5: what the robot knows, and the law's target from it.
  view_->refresh(i);
  Robot& r = robots_[i];
  // A law on positions is told the robots' estimates, which the virtual generators follow then.
  const Generators told = localization_ && !law_->moves_virtual_generators()
                              ? Generators::virtual_generators
                              : law_->generators();
  r.virtual_target = guarded(i, "coverage law", config_.law.type, [&] {
    Knowledge known = view_->knowledge(i, told);
    // A robot that maps Ω computes its cell in Ω as it believes it.
    if (mapping_) believe(known, *mapping_->belief(i).integrator);
    const Vec2 t = law_->target(r, known);
    if (!is_finite(t))
      throw std::invalid_argument(fmt::format("a target must be finite, found ({}, {})", t.x, t.y));
    return t;
  });
  // Algorithm 2, lines 2-4: an obstacle boundary Voronoi region projects its target, onto
  // the free space of the robot's body (as the robot believes it, when it maps Ω).
  const Environment& space = mapping_ ? mapping_->free_space(i, r.position) : free_space(i);
  r.projected = !space.contains(r.virtual_target);
  r.real_target = r.projected ? space.closest_point(r.virtual_target) : r.virtual_target;
  // At its real target: for a projected target, at a closest point of Ω to the virtual one
  // (when several are equally close, the planner's is as good as the controller's), or
  // settled at a closest point of Ω to the goal it was given, which the target has not left
  // by more than the tolerance: a target inside a thin wall that crosses the wall's midline
  // by less than the tolerance moves its projection to the far face, and the robot, never
  // handed that target (it has not moved enough), would otherwise wait for ever.
  // Near the closest point, or as near the goal as it to rounding: a robot whose distance to
  // the goal is merely within the tolerance of the least may stand far from every closest
  // point (office, robot 28: settled beside a corner of a T-wall, 0.06 m from the
  // projection of a target that had moved 0.15 m, and never handed it).
  // Where it is, as far as it knows, and as near as it can tell (with a localization, not
  // nearer than kReachDeviations standard deviations of its estimate's jitter).
  const Vec2 at = known_position(r);
  const double near = within_reach();
  const auto at_closest_point = [&](Vec2 goal, Vec2 closest) {
    return distance(at, closest) <= near ||
           distance(at, goal) - distance(closest, goal) <= space.tolerance();
  };
  // A robot that maps Ω may find a target unreachable before it knows the obstacle whole
  // (the paper's Fig. 4, with an obstacle not yet mapped): its planner settled at the closest
  // point it could reach, which the Lemma-2 check (arrive()) holds to Ω itself.
  const bool discovered = mapping_ && r.status == PlanStatus::projected &&
                          distance(r.virtual_target, r.assigned) <= tol_.position;
  const bool at_target =
      discovered ||
      (r.projected ? at_closest_point(r.virtual_target, r.real_target) ||
                         ((r.status == PlanStatus::projected || r.status == PlanStatus::reached) &&
                          distance(r.virtual_target, r.assigned) <= tol_.position &&
                          !space.contains(r.assigned) &&
                          at_closest_point(r.assigned, space.closest_point(r.assigned)))
                   : distance(r.real_target, at) <= near);
  r.stable = is_settled(r.status) && at_target &&
             guarded(i, "coverage law", config_.law.type, [&] { return law_->at_rest(r, tol_); });
  if (r.stable) return;
  // A robot that stopped at its goal by its estimate, and finds by a later fix that it is not
  // there, is handed its goal again: the projection of the target it was set for, for a
  // virtual target it has already found unreachable.
  if (localization_ && !at_target &&
      (r.status == PlanStatus::reached || r.status == PlanStatus::projected) &&
      distance(r.virtual_target, r.assigned) <= tol_.position)
    set_goal(r, r.status == PlanStatus::projected ? space.closest_point(r.assigned) : r.goal);
  // Only a target that moved (by more than the position tolerance) restarts the planner: a
  // goal it reached, found unreachable or gave up on is never handed to it again (it would
  // only do the same again), and periodic updates cannot keep restarting a robot on its way
  // round an obstacle.
  // A robot on its way keeps its planner's state for the moved goal (Planner::move_goal).
  // Under either policy the virtual target decides: its projection jumps across a thin
  // wall's midline while the target itself moves by a hair.
  if (distance(r.virtual_target, r.assigned) > tol_.position) {
    const Vec2 goal = planner_goal(r);
    if (is_settled(r.status)) {
      set_goal(r, goal);
    } else {
      move_goal(r, goal);
    }
    r.assigned = r.virtual_target;
  }
}

void CoverageController::believe(Knowledge& k, const CellIntegrator& integrator) {
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

Vec2 CoverageController::planner_goal(const Robot& r) const {
  // The virtual target, which the planner finds unreachable itself (discover), or, with Ω
  // known, its projection from the start (known).
  return config_.projection == ProjectionPolicy::known ? r.real_target : r.virtual_target;
}

double CoverageController::excursion(const Environment& space, Vec2 p, Vec2 q) const {
  // The stretch outside Ω runs from where the motion leaves to where it comes back; the
  // largest distance from Ω of its points, finely sampled, is the excursion.
  const Vec2 out = space.advance(p, q);
  const Vec2 back = space.advance(q, p);
  constexpr int kSamples = 32;
  double depth = 0.0;
  for (int k = 0; k <= kSamples; ++k) {
    const Vec2 x = out + (static_cast<double>(k) / kSamples) * (back - out);
    depth = std::max(depth, distance(x, space.closest_point(x)));
  }
  return depth;
}

void CoverageController::set_goal(Robot& r, Vec2 goal) {
  r.goal = goal;
  r.planner_goal = in_planner_frame(r, goal);
  guarded(r.id, "planner", r.planner->name(), [&] { r.planner->set_goal(r.planner_goal); });
  r.status = PlanStatus::moving;
}

void CoverageController::move_goal(Robot& r, Vec2 goal) {
  r.goal = goal;
  r.planner_goal = in_planner_frame(r, goal);
  guarded(r.id, "planner", r.planner->name(), [&] { r.planner->move_goal(r.planner_goal); });
}

Vec2 CoverageController::planner_position(const Robot& r) const {
  return localization_ ? localization_->odometry(r.id) : r.position;
}

Vec2 CoverageController::in_planner_frame(Robot& r, Vec2 p) {
  if (!localization_) return p;
  const Vec2 q = p - (localization_->estimate(r.id) - localization_->odometry(r.id));
  // A fix's noise must not make a goal the robot can reach one it cannot: moved by the fix's
  // error, a goal near a wall lands in it, and the planner walks round all of Ω to find it
  // unreachable (e-puck with 2 cm of tracking noise: a goal 2.8 cm from the grown wall, moved
  // 3.6 cm by a fix, sent its robot round the U). A goal in an obstacle on purpose (discover)
  // stays there.
  const Environment& space = free_space(r.id);
  return space.contains(p) && !space.contains(q) ? space.closest_point(q) : q;
}

double CoverageController::reach(double sigma) const {
  return std::max(tol_.position, kReachDeviations * sigma);
}

double CoverageController::planner_reach() const {
  return reach(sensing_.position_sigma);
}

double CoverageController::within_reach() const {
  return localization_ ? reach(localization_->estimate_jitter(step_)) : tol_.position;
}

void CoverageController::loop2(Kernel& k, std::uint32_t i) {
  Robot& r = robots_[i];
  const Vec2 before = r.position;
  if (localization_) {
    const double error = distance(localization_->estimate(i), r.position);
    localization_error_sum_ += error;
    localization_error_max_ = std::max(localization_error_max_, error);
    ++localization_steps_;
    // Fixes moved the goal in the odometry's frame, where the planner works, by more than the
    // robot can tell (smaller moves, the fixes' noise, would keep a planner's episode from
    // ever ending, as loop 1's targets would); not while a step the planner proposed is still
    // being carried out.
    if (!is_settled(r.status) && r.give_way == 0.0 && !r.waypoint &&
        distance(in_planner_frame(r, r.goal), r.planner_goal) > within_reach())
      move_goal(r, r.goal);
  }
  if (r.give_way > 0.0) {
    give_way(r);
  } else if (!is_settled(r.status) && r.waypoint) {
    // On the way to the planner's last step, as far as the neighbours allow.
    if (!follow_waypoint(k, r)) return;
  } else if (!is_settled(r.status) && localization_ &&
             distance(planner_position(r), r.planner_goal) <= planner_reach()) {
    // As near its planner's goal as it can tell (every motion, however short, drifts an
    // odometry; fixes move an estimate): there.
    if (!arrive(k, r, PlanStatus::reached)) return;
  } else if (!is_settled(r.status)) {
    // Algorithm 2, line 5: a planner step toward the real target, in the real world.
    PlanStep s = planner_step(k, r);
    // Most steps stay in Ω whole: the segment is then checked once, not again below. A body
    // moves in Ω shrunk by its radius: it stops where it would touch a wall.
    const Environment& space = free_space(i);
    bool whole = space.segment_inside(r.position, s.next);
    if (r.displaced && !whole && r.planner->avoids_obstacles()) {
      // A detour round a neighbour took the robot where its planner's way runs into a wall:
      // the planner starts afresh from here.
      set_goal(r, r.goal);
      s = planner_step(k, r);
      whole = space.segment_inside(r.position, s.next);
    }
    r.displaced = false;
    Vec2 next = whole ? s.next : space.advance(r.position, s.next);
    // Out of Ω: a motion that ends in an obstacle, or cuts through one deeper than the
    // position tolerance, ends the run with the robot where it crossed ∂Ω. A corner cut
    // within the tolerance (by a micrometre) on the way to a point of Ω is a graze.
    bool departed = false;
    if (!r.planner->avoids_obstacles() && !(next == s.next)) {
      departed = !space.contains(s.next) || excursion(space, r.position, s.next) > tol_.position;
      if (!departed) next = s.next;
    }
    if (r.planner->avoids_obstacles() && !(whole && next == s.next) &&
        !space.segment_inside(r.position, next)) {
      throw std::logic_error(
          fmt::format("robot {} left the environment at t={} s: ({}, {}) -> ({}, {})", i,
                      k.now().seconds(), r.position.x, r.position.y, next.x, next.y));
    }
    if ((avoidance_ || kinematics_) && !departed) {
      r.waypoint = PlanStep{next, s.status};
      r.waypoint_from = r.position;
      if (!follow_waypoint(k, r)) return;
    } else {
      move_to(r, next);
      if (departed) {
        departure_ = LeftEnvironment{i, k.now(), r.goal, next};
        k.fingerprint().fold_state(next.x);
        k.fingerprint().fold_state(next.y);
        if (observer_ != nullptr) observer_->on_motion(k.now(), r);
        k.stop();
        return;
      }
      if (!arrive(k, r, s.status)) return;
    }
  }
  if (avoidance_) r.velocity = (r.position - before) / config_.loop2_period.seconds();
  if (localization_ && !(r.position == before)) localization_->moved(i, r.position - before);
  if (r.projected) ++r.target_outside_steps;
  if (r.status == PlanStatus::stalled) r.stalled_time += config_.loop2_period.seconds();
  if (law_->moves_virtual_generators()) {
    // Line 6: the virtual generator steps toward the virtual target as if Ω were convex.
    const Vec2 d = r.virtual_target - r.virtual_generator;
    const double dn = norm(d);
    if (dn > 0.0) {
      r.virtual_generator = dn <= step_ ? r.virtual_target : r.virtual_generator + (step_ / dn) * d;
      state_->move(Generators::virtual_generators, i, r.virtual_generator);
    }
  } else {
    // No virtual generators: they follow the positions, as the robots know them.
    const Vec2 g = localization_ ? known_position(r) : r.position;
    if (!(r.virtual_generator == g)) {
      r.virtual_generator = g;
      state_->move(Generators::virtual_generators, i, r.virtual_generator);
    }
  }
  if (config_.mode == LoopMode::classic && is_settled(r.status)) {
    k.schedule_at(k.now() + config_.loop2_period, loop1_kind_, i, event_class::loop1);
  }
  if (observer_ != nullptr) observer_->on_motion(k.now(), r);
}

Vec2 CoverageController::known_position(const Robot& r) {
  if (!localization_) return r.position;
  const Vec2 e = localization_->estimate(r.id);
  const Environment& space = free_space(r.id);
  return space.contains(e) ? e : space.closest_point(e);
}

PlanStep CoverageController::planner_step(const Kernel& k, Robot& r) {
  // The planner works in its frame: from where it believes the robot is, the walls where it
  // senses them from there.
  const Vec2 known = planner_position(r);
  const bool exact = known == r.position;
  const PlanStep s = guarded(r.id, "planner", r.planner->name(), [&] {
    SensorReading reading = sensor_->reading(r.id, r.position);
    if (!exact) shift(reading, known - r.position);
    const PlanStep step = r.planner->step(reading, step_);
    if (!is_finite(step.next))
      throw std::invalid_argument(
          fmt::format("a step must be a finite point, found ({}, {})", step.next.x, step.next.y));
    return step;
  });
  // A robot moves at most its step length per planner step, whatever the planner asks (up to
  // the rounding of the positions compared, which a tiny step may not exceed relatively).
  if (!(distance(known, s.next) <= step_ * (1.0 + 1e-9) + distance_rounding(known, s.next))) {
    throw std::runtime_error(fmt::format(
        "robot {}'s planner {} proposed a step of {} m at t={} s; the step length is {} m", r.id,
        r.planner->name(), distance(known, s.next), k.now().seconds(), step_));
  }
  // The same displacement from where the robot really is.
  return exact ? s : PlanStep{r.position + (s.next - known), s.status};
}

void CoverageController::move_to(Robot& r, Vec2 next) {
  const double length = distance(r.position, next);
  if (mapping_) mapping_->moved(r.id, next, length, kernel_.now());
  r.path_length += length;
  r.position = next;
  if (near_) near_->moved(r.id, next);
  state_->move(Generators::positions, r.id, next);
  view_->moved(r.id);
}

bool CoverageController::arrive(Kernel& k, Robot& r, PlanStatus status) {
  r.status = status;
  r.stable = false;
  if (mapping_ && is_settled(status)) {
    // Found unreachable a goal its map still places in free space: an obstacle not yet known
    // whole (the paper's Fig. 4 without a map).
    if (status == PlanStatus::projected && mapping_->free_space(r.id, r.position).contains(r.goal))
      ++discoveries_;
    mapping_->settled(r.id, r.position, k.now());
  }
  if (config_.radius > 0.0 && space_->overlaps_boundary(r.position)) ++wall_contacts_;
  if (status == PlanStatus::projected && !unreachable(r)) {
    failure_ = PlannerFailure{r.id, k.now(), r.goal, r.position};
    k.stop();
    return false;
  }
  // A planner that gives up on a target outside Ω: the target is unreachable, so the
  // robot goes to its projection instead.
  if (r.status == PlanStatus::stalled && r.projected && !(r.goal == r.real_target)) {
    r.stalled_time += config_.loop2_period.seconds();
    set_goal(r, r.real_target);
  }
  return true;
}

bool CoverageController::unreachable(const Robot& r) const {
  const Environment& space = free_space(r.id);
  if (!localization_) return !space.contains(r.goal);
  // The planner's goal among the walls as it senses them; one nearer the boundary than the
  // robot can tell, or than its odometry has drifted while it walked, may have crossed it as
  // fixes and drift moved it.
  const Vec2 p = r.planner_goal - (localization_->odometry(r.id) - r.position);
  const double margin =
      std::max(within_reach(), reach(localization_->odometry_jitter(r.path_length)));
  return !space.contains(p) || space.boundary_distance(p) <= margin;
}

template <class F>
void CoverageController::for_each_near(Vec2 p, double radius, F&& f) const {
  // In increasing index either way: the same order as a loop over every robot.
  if (!near_ || radius > near_range_) {
    for (const Robot& o : robots_)
      f(o);
    return;
  }
  near_->candidates(p, near_ids_);
  for (const std::uint32_t j : near_ids_)
    f(robots_[j]);
}

void CoverageController::sense_neighbors(const Robot& r) {
  // Those within the avoidance's range and in sight.
  const double range =
      avoidance_->range(config_.radius, config_.max_speed, config_.loop2_period.seconds());
  neighbors_.clear();
  for_each_near(r.position, range, [&](const Robot& o) {
    if (o.id == r.id || !within(o.position, r.position, range) ||
        !env_.segment_inside(r.position, o.position))
      return;
    neighbors_.push_back(SensedNeighbor{o.position, o.velocity});
  });
}

bool CoverageController::arrive_at_waypoint(Kernel& k, Robot& r) {
  const PlanStatus status = r.waypoint->status;
  r.waypoint.reset();
  if (r.deadlocked) ++deadlocks_resolved_;
  r.deadlocked = false;
  return arrive(k, r, status);
}

Vec2 CoverageController::drive(Robot& r, Vec2 to) {
  if (!kinematics_) return to;
  const BodyMotion m =
      kinematics_->move(r.position, r.body, r.driving_to, to, config_.loop2_period.seconds());
  r.body = m.state;
  r.driving_to = to;
  if (m.hard_stop) ++hard_stops_;
  turn_time_ += m.turning;
  return m.arrived ? to : m.position;
}

Vec2 CoverageController::avoiding_velocity(const Robot& r, Vec2 preferred, double max_speed) {
  sense_neighbors(r);
  return guarded(r.id, "collision avoidance", config_.avoidance.type, [&] {
    const Vec2 v =
        avoidance_->velocity(AvoidanceQuery{r.position, r.velocity, preferred, config_.radius,
                                            max_speed, config_.loop2_period.seconds(), neighbors_});
    if (!is_finite(v) || !(norm(v) <= max_speed * (1 + 1e-9)))
      throw std::invalid_argument(fmt::format(
          "a velocity must be finite and at most {} m/s, found ({}, {})", max_speed, v.x, v.y));
    return v;
  });
}

bool CoverageController::follow_waypoint(Kernel& k, Robot& r) {
  const PlanStep w = *r.waypoint;
  const double dt = config_.loop2_period.seconds();
  const Environment& space = free_space(r.id);
  // A step that ends the planner's episode (at the goal, or settled at the closest point)
  // is followed to its point; a step on the way only as far along its direction, so that a
  // detour round a neighbour is kept rather than undone.
  const bool last = w.status != PlanStatus::moving;
  const Vec2 planned_way = w.next - r.waypoint_from;
  const double planned_length = norm(planned_way);
  const auto left = [&](Vec2 p) {
    return last || planned_length == 0.0 ? distance(p, w.next)
                                         : dot(w.next - p, planned_way) / planned_length;
  };
  const Vec2 preferred =
      last || planned_length == 0.0 || r.position == r.waypoint_from
          ? (w.next - r.position) / dt
          : (std::max(0.0, left(r.position)) / planned_length / dt) * planned_way;
  Vec2 to = w.next;
  bool blocked = false;
  if (avoidance_) {
    // No faster than the waypoint needs: a detour never passes it.
    const Vec2 v = avoiding_velocity(r, preferred, norm(preferred));
    to = v == preferred ? w.next : r.position + dt * v;
    // A detour keeps the waypoint in sight, within the free space; otherwise only the part of
    // the velocity along the way to it is taken.
    if (!(to == w.next) &&
        !(space.segment_inside(r.position, to) && space.segment_inside(to, w.next))) {
      const Vec2 d = w.next - r.position;
      const double f = std::clamp(dot(to - r.position, d) / norm2(d), 0.0, 1.0);
      to = f == 1.0 ? w.next : r.position + f * d;
    }
    // Never nearer to a body than touching, whatever the avoidance chose.
    const double g = clear_fraction(r, to);
    if (g < 1.0) to = r.position + g * (to - r.position);
    // Blocked: a tenth of the way or less made good (pushed back counts as blocked).
    const double before = left(r.position);
    blocked = before - left(to) < 0.1 * before;
  }
  // The body carries the motion out as far as it can in the step; the way to `to` is clear
  // and free, and the body stays on it.
  const Vec2 at = drive(r, to);
  move_to(r, at);
  if (!avoidance_) return at == w.next ? arrive_at_waypoint(k, r) : true;
  // A deadlock begins after kDeadlockTime blocked, and lasts until the robot reaches a
  // planner step again.
  r.blocked_time = blocked ? r.blocked_time + dt : 0.0;
  if (r.deadlocked) {
    deadlock_time_ += dt;
  } else if (r.blocked_time >= kDeadlockTime) {
    r.deadlocked = true;
    ++deadlocks_;
    deadlock_time_ += r.blocked_time;
  }
  // On the way, nine tenths of the step along its direction will do (for a body at rest, or
  // one that can change direction at once): the planner steps on from where the robot is.
  if (at == w.next ||
      (!last && (!kinematics_ || r.body.speed == 0.0) && left(at) <= 0.1 * planned_length)) {
    r.displaced = !(at == w.next);
    return arrive_at_waypoint(k, r);
  }
  if (blocked && std::fmod(r.blocked_time + 0.5 * dt, kDeadlockTime) < dt) resolve(r);
  return true;
}

void CoverageController::resolve(Robot& r) {
  // Who stands on the waypoint, if anyone.
  Robot* occupant = nullptr;
  for (Robot& o : robots_) {
    if (o.id != r.id && distance(o.position, r.waypoint->next) < 2.0 * config_.radius &&
        (occupant == nullptr ||
         distance(o.position, r.waypoint->next) < distance(occupant->position, r.waypoint->next)))
      occupant = &o;
  }
  if (occupant == nullptr) {
    // Held up by its neighbours' avoidance: the planner is asked again from here.
    r.waypoint.reset();
    r.displaced = true;
  } else if (occupant->deadlocked && occupant->id < r.id) {
    // Two robots in each other's way: the larger id gives way, or, if it has no room to (in
    // a dead end, hemmed in by others), the other one.
    if (!start_giving_way(r, occupant->position) && occupant->give_way == 0.0)
      start_giving_way(*occupant, r.position);
  } else if (!occupant->deadlocked && occupant->give_way == 0.0 && is_settled(occupant->status)) {
    // A robot settled on the way steps aside, then returns to its goal.
    start_giving_way(*occupant, r.position);
  }
}

bool CoverageController::start_giving_way(Robot& r, Vec2 from) {
  // Two body diameters to its own right as it faces the robot it makes room for (the side
  // ORCA's bias passes on), else back and right, straight back, back and left, or left: the
  // first where the walls and the other bodies leave it a body's radius of way, else the
  // roomiest.
  const Environment& space = free_space(r.id);
  const Vec2 away = r.position - from;
  const Vec2 unit = away / norm(away);
  const double length = 4.0 * config_.radius;
  double room = 0.0;
  r.give_way_to = r.position;
  for (const double turn : {std::numbers::pi / 2, std::numbers::pi / 4, 0.0, -std::numbers::pi / 4,
                            -std::numbers::pi / 2}) {
    const double c = std::cos(turn), s = std::sin(turn);
    const Vec2 d{c * unit.x - s * unit.y, s * unit.x + c * unit.y};
    const Vec2 q = space.advance(r.position, r.position + length * d);
    const double way = clear_fraction(r, q) * distance(r.position, q);
    if (way > room) {
      room = way;
      r.give_way_to = q;
    }
    if (way >= config_.radius) break;
  }
  if (room < 0.5 * config_.radius) {
    r.give_way_to = r.position;
    return false;  // no room to give way
  }
  // As long as it takes to get there (for a body with a heading, to turn round first), twice
  // over: a neighbour in the way may hold it up.
  double time = length / config_.max_speed;
  if (kinematics_) {
    const KinematicLimits& l = kinematics_->limits();
    time = travel(std::numbers::pi, 0.0, l.turn_rate, l.angular_acceleration, INFINITY).time +
           travel(length, 0.0, l.speed, l.acceleration, INFINITY).time;
  }
  r.give_way = std::max(2.0 * time, config_.loop2_period.seconds());
  r.status = PlanStatus::moving;
  r.stable = false;
  ++give_ways_;
  return true;
}

void CoverageController::give_way(Robot& r) {
  const double dt = config_.loop2_period.seconds();
  const Vec2 to = r.give_way_to;
  const double g = clear_fraction(r, to);
  const Vec2 at = drive(r, g < 1.0 ? r.position + g * (to - r.position) : to);
  move_to(r, at);
  r.give_way = at == to ? 0.0 : std::max(0.0, r.give_way - dt);
  if (r.deadlocked) deadlock_time_ += dt;
  if (r.give_way == 0.0) {
    // Back to its goal, with its planner started afresh from here.
    r.waypoint.reset();
    r.blocked_time = 0.0;
    set_goal(r, r.goal);
  }
}

double CoverageController::clear_fraction(const Robot& r, Vec2 to) const {
  const Vec2 d = to - r.position;
  const double a = norm2(d);
  if (a == 0.0) return 1.0;
  const double reach = 2.0 * config_.radius;
  double g = 1.0;
  for_each_near(r.position, reach + std::sqrt(a), [&](const Robot& o) {
    if (o.id == r.id || !within(o.position, r.position, reach + std::sqrt(a))) return;
    // The first point of the motion nearer to o than touching (or than it already is).
    const Vec2 e = r.position - o.position;
    const double b = 2.0 * dot(e, d);
    if (b >= 0.0) return;  // moving away from o
    const double least = std::min(reach, norm(e));
    const double c = norm2(e) - least * least;
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return;
    const double s = (-b - std::sqrt(disc)) / (2.0 * a);
    g = std::min(g, std::max(0.0, s));
  });
  return g;
}

void CoverageController::check_bodies() {
  // A sweep along x: only pairs nearer in x than both the least gap so far and a contact
  // need a distance.
  const double r2 = 2.0 * config_.radius;
  const double touch = r2 - env_.tolerance();
  std::vector<std::uint32_t> order(robots_.size());
  for (std::uint32_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return robots_[a].position.x < robots_[b].position.x ||
           (robots_[a].position.x == robots_[b].position.x && a < b);
  });
  std::vector<bool> touching(robots_.size(), false);
  double least = INFINITY;
  for (std::size_t a = 0; a < order.size(); ++a) {
    const Vec2 p = robots_[order[a]].position;
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const Vec2 q = robots_[order[b]].position;
      if (q.x - p.x >= std::max(least, r2)) break;
      const double d = distance(p, q);
      least = std::min(least, d);
      if (d < touch) touching[order[a]] = touching[order[b]] = true;
    }
  }
  if (order.size() >= 2) body_gap_min_ = std::fmin(body_gap_min_, least - r2);
  for (bool t : touching)
    if (t) contact_time_ += config_.loop2_period.seconds();
}

void CoverageController::check(Kernel& k) {
  if (config_.radius > 0.0) check_bodies();
  for (const Robot& r : robots_) {
    k.fingerprint().fold_state(r.position.x);
    k.fingerprint().fold_state(r.position.y);
    k.fingerprint().fold_state(r.virtual_generator.x);
    k.fingerprint().fold_state(r.virtual_generator.y);
  }
  bool all_stable = true, all_resting = true;
  for (const Robot& r : robots_) {
    all_stable = all_stable && r.stable;
    // Stuck: stalled short of a target that has not moved, with the law at rest (the paper's
    // virtual generator on its target).
    const bool stuck = r.status == PlanStatus::stalled &&
                       distance(r.virtual_target, r.assigned) <= tol_.position &&
                       law_->at_rest(r, tol_);
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
