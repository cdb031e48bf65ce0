#include "robot/coverage_controller.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "planners/planner_map.hpp"
#include "planners/planner_registry.hpp"
#include "robot/belief_layer.hpp"
#include "robot/body_checks.hpp"
#include "robot/coverage_law_registry.hpp"
#include "robot/event_classes.hpp"
#include "robot/guarded_call.hpp"
#include "robot/ideal_view.hpp"
#include "robot/mapping.hpp"
#include "robot/motion_layer.hpp"
#include "robot/networked_view.hpp"
#include "robot/planning_layer.hpp"

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
  belief_ = std::make_unique<BeliefLayer>(
      kernel_, env, density, starts, config_, step_, tol_.position,
      [this](std::uint32_t i) { return robots_[i].position; },
      [this](std::uint32_t i) -> const Environment& { return free_space(i); });
  planner_space_ = std::make_unique<PlannerSpace>(env, *space_, config_.radius,
                                                  belief_->map_frame() ? belief_->inflation() : 0.0,
                                                  config_.inflation);
  // Each part of the free space has its planners' shared maps, built for the first robot in it
  // (centralized, with the ideal network, one sensed map for the robots' planners too).
  std::vector<std::optional<PlannerSource>> sources(planner_space_->part_count());
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
    const std::size_t plan_part = planner_space_->add(starts[i], part);
    Robot r;
    r.id = i;
    r.position = r.virtual_generator = r.virtual_target = r.real_target = r.goal = r.assigned =
        starts[i];
    if (make_planner) {
      r.planner = make_planner(i);
    } else {
      if (!sources[plan_part])
        sources[plan_part] = planner_source(
            config_.planner, PlannerContext{planner_space_->part(plan_part), belief_->sensing(),
                                            config_.network.channel.is_ideal()});
      r.planner = (*sources[plan_part])();
    }
    if (wrap) r.planner = wrap(std::move(r.planner));
    robots_.push_back(std::move(r));
  }
  state_ = std::make_unique<GeneratorState>(integrator_, starts);
  law_ = make_coverage_law(config_.law, LawContext{env, density, integrator_});
  const bool ideal = config_.network.channel.is_ideal();
  Mapping* mapping = belief_->mapping();
  // Decentralized, each robot's map planner also takes the walls of the readings it hears.
  const PlannerEntry* entry = planner_registry().find(config_.planner.type);
  if (mapping && !ideal &&
      (plans_on_sensed_map(config_.planner.params) || (entry != nullptr && entry->learns)))
    mapping->on_learn([this](std::uint32_t i, const Scan& s) { planning_->learn(robots_[i], s); });
  if (ideal) {
    view_ = std::make_unique<IdealView>(*state_);
  } else {
    view_ = std::make_unique<NetworkedView>(kernel_, env, config_.network, *state_, mapping);
  }
  sensor_ = std::make_unique<SensorModel>(
      kernel_, [this](std::uint32_t i) -> const Environment& { return free_space(i); },
      config_.sensor, robots_.size(), [this](std::uint32_t i) { return robots_[i].position; });
  planning_ = std::make_unique<PlanningLayer>(kernel_, *belief_, *sensor_, step_, config_.radius,
                                              *space_, part_, *planner_space_);
  motion_ = std::make_unique<MotionLayer>(
      kernel_, env, config_, robots_,
      MotionHost{[this](Robot& r, Vec2 p) { move_to(r, p); },
                 [this](Robot& r, PlanStatus s) { return arrive(kernel_, r, s); },
                 [this](Robot& r) { planning_->set_goal(r, r.goal); },
                 [this](std::uint32_t i) -> const Environment& { return free_space(i); }});
  if (config_.radius > 0.0)
    bodies_ =
        std::make_unique<BodyChecks>(env, *space_, config_.radius, config_.loop2_period.seconds());
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
  belief_->start(t0, robots_);
  view_->motion_clock(t0 + config_.loop2_period, config_.loop2_period);
  view_->start(t0);
  kernel_.schedule_periodic(Period::from_ns(config_.sample_period.ns()), t0, sample_kind_,
                            event_class::world, event_class::sample);
  kernel_.schedule_periodic(Period::from_ns(config_.loop2_period.ns()), t0 + config_.loop2_period,
                            check_kind_, event_class::world, event_class::check);
}

void CoverageController::loop1(std::uint32_t i) {
  if (!view_->ready(i)) return;
  // Algorithm 1, lines 3-5: what the robot knows, and the law's target from it.
  view_->refresh(i);
  Robot& r = robots_[i];
  // A law on positions is told the robots' estimates, which the virtual generators follow then.
  const Generators told = belief_->localization() && !law_->moves_virtual_generators()
                              ? Generators::virtual_generators
                              : law_->generators();
  r.virtual_target = guarded_call(i, "coverage law", config_.law.type, kernel_.now(), [&] {
    Knowledge known = view_->knowledge(i, told);
    // A robot that maps Ω computes its cell in Ω as it believes it.
    if (const Mapping* m = belief_->mapping()) belief_->believe(known, *m->belief(i).integrator);
    const Vec2 t = law_->target(r, known);
    if (!is_finite(t))
      throw std::invalid_argument(fmt::format("a target must be finite, found ({}, {})", t.x, t.y));
    return t;
  });
  // Algorithm 2, lines 2-4: an obstacle boundary Voronoi region projects its target, onto
  // the free space of the robot's body (as the robot believes it, when it maps Ω).
  const Environment& space = belief_->believed_free_space(r);
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
  const Vec2 at = belief_->known_position(r);
  const double near = belief_->within_reach();
  const auto at_closest_point = [&](Vec2 goal, Vec2 closest) {
    return distance(at, closest) <= near ||
           distance(at, goal) - distance(closest, goal) <= space.tolerance();
  };
  // A robot that maps Ω may find a target unreachable before it knows the obstacle whole
  // (the paper's Fig. 4, with an obstacle not yet mapped): its planner settled at the closest
  // point it could reach, which the Lemma-2 check (arrive()) holds to Ω itself.
  const bool discovered = belief_->mapping() && r.status == PlanStatus::projected &&
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
             guarded_call(i, "coverage law", config_.law.type, kernel_.now(),
                          [&] { return law_->at_rest(r, tol_); });
  if (r.stable) return;
  // A robot that stopped at its goal by its estimate, and finds by a later fix that it is not
  // at its target, is handed its target as it is now (the projection, for a virtual target it
  // has already found unreachable): handed the goal it was set for, it would go back there
  // for ever when the target has since moved by less than the tolerance but the fixes keep it
  // farther than it can tell (office, 5 mm tracking: robot 0 re-handed a goal 4.2 cm from its
  // target, and never within 5 cm of the target).
  if (belief_->localization() && !at_target &&
      (r.status == PlanStatus::reached || r.status == PlanStatus::projected) &&
      distance(r.virtual_target, r.assigned) <= tol_.position) {
    planning_->set_goal(r, r.status == PlanStatus::projected ? space.closest_point(r.virtual_target)
                                                             : planner_goal(r));
    r.assigned = r.virtual_target;
  }
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
      planning_->set_goal(r, goal);
    } else {
      planning_->move_goal(r, goal);
    }
    r.assigned = r.virtual_target;
  }
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

void CoverageController::loop2(Kernel& k, std::uint32_t i) {
  Robot& r = robots_[i];
  const Vec2 before = r.position;
  if (belief_->localization()) {
    belief_->tick(r);
    // A planner on Ω's map plans again from where a fix moved the estimate.
    if (belief_->estimate_jumped(r) && !is_settled(r.status) && r.give_way == 0.0 && !r.waypoint)
      planning_->set_goal(r, r.goal);
    // Fixes moved the goal in the odometry's frame, where the planner works, by more than the
    // robot can tell (smaller moves, the fixes' noise, would keep a planner's episode from
    // ever ending, as loop 1's targets would); not while a step the planner proposed is still
    // being carried out.
    if (!is_settled(r.status) && r.give_way == 0.0 && !r.waypoint &&
        distance(belief_->in_planner_frame(r, r.goal), r.planner_goal) > belief_->within_reach())
      planning_->move_goal(r, r.goal);
  }
  if (r.give_way > 0.0) {
    motion_->give_way(r);
  } else if (!is_settled(r.status) && r.waypoint) {
    // On the way to the planner's last step, as far as the neighbours allow.
    if (!motion_->follow_waypoint(r)) return;
  } else if (!is_settled(r.status) && belief_->localization() &&
             distance(belief_->planner_position(r), r.planner_goal) <= belief_->planner_reach()) {
    // As near its planner's goal as it can tell (every motion, however short, drifts an
    // odometry; fixes move an estimate): there.
    if (!arrive(k, r, PlanStatus::reached)) return;
  } else if (!is_settled(r.status)) {
    // Algorithm 2, line 5: a planner step toward the real target, in the real world.
    PlanStep s = planning_->step(r);
    // Most steps stay in Ω whole: the segment is then checked once, not again below. A body
    // moves in Ω shrunk by its radius: it stops where it would touch a wall.
    const Environment& space = free_space(i);
    bool whole = space.segment_inside(r.position, s.next);
    if (r.displaced && !whole && r.planner->avoids_obstacles()) {
      // A detour round a neighbour took the robot where its planner's way runs into a wall:
      // the planner starts afresh from here.
      planning_->set_goal(r, r.goal);
      s = planning_->step(r);
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
    if (motion_->follows_waypoints() && !departed) {
      r.waypoint = PlanStep{next, s.status};
      r.waypoint_from = r.position;
      if (!motion_->follow_waypoint(r)) return;
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
  if (motion_->avoids_collisions())
    r.velocity = (r.position - before) / config_.loop2_period.seconds();
  if (belief_->localization() && !(r.position == before)) belief_->moved(r, r.position - before);
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
    const Vec2 g = belief_->localization() ? belief_->known_position(r) : r.position;
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

void CoverageController::move_to(Robot& r, Vec2 next) {
  const double length = distance(r.position, next);
  belief_->moving(r, next, length, kernel_.now());
  r.path_length += length;
  r.position = next;
  motion_->moved(r, next);
  state_->move(Generators::positions, r.id, next);
  view_->moved(r.id);
}

bool CoverageController::arrive(Kernel& k, Robot& r, PlanStatus status) {
  r.status = status;
  r.stable = false;
  belief_->arrived(r, status, k.now());
  if (bodies_) bodies_->arrived(r.position);
  if (status == PlanStatus::projected && !belief_->goal_unreachable(r)) {
    failure_ = PlannerFailure{r.id, k.now(), r.goal, r.position};
    k.stop();
    return false;
  }
  // A planner that gives up on a target outside Ω: the target is unreachable, so the
  // robot goes to its projection instead.
  if (r.status == PlanStatus::stalled && r.projected && !(r.goal == r.real_target)) {
    r.stalled_time += config_.loop2_period.seconds();
    planning_->set_goal(r, r.real_target);
  }
  return true;
}

void CoverageController::check(Kernel& k) {
  if (bodies_) bodies_->after_tick(robots_);
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
