#include "analysis/contract/planner_contract.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/random_stream.hpp"
#include "geometry/configuration_space.hpp"
#include "geometry/environment.hpp"
#include "geometry/placement.hpp"
#include "geometry/reversals.hpp"
#include "geometry/visibility_graph.hpp"
#include "planners/planner_registry.hpp"
#include "planners/tangent_bug.hpp"
#include "scenarios/obstacle_course.hpp"

namespace covsim {

namespace {

constexpr std::uint64_t kCasesPerMap = 10;

std::string number(double v) {
  return std::isinf(v) ? "inf" : fmt::format("{}", v);
}

// One map of the suite, shared by kCasesPerMap consecutive cases.
struct ContractMap {
  ObstacleCourseSpec spec;
  std::unique_ptr<Environment> env;
  std::unique_ptr<VisibilityGraph> graph;
  double boundary_length = 0.0;
  double narrowest = 0.0;  // passage, for planners that need a fine enough map
  Box below, above;        // combs: where starts and goals lie
};

ContractMap make_map(std::uint64_t seed, std::uint64_t group, CaseFamily family, double radius) {
  if (radius > 0.0 && family == CaseFamily::combs)
    throw std::invalid_argument("a radius applies to the courses family, not to combs");
  RandomStream rng(seed, group, "contract-map");
  ContractMap m;
  ObstacleCourse c;
  if (family == CaseFamily::combs) {
    const CombCourse comb = comb_course(rng.next_u64());
    c = comb.course;
    m.below = comb.below;
    m.above = comb.above;
  } else {
    m.spec.width = rng.uniform(6.0, 12.0);
    m.spec.height = rng.uniform(6.0, 12.0);
    m.spec.obstacles = static_cast<std::uint32_t>(3 + rng.below(7));
    m.spec.clearance = rng.uniform(0.1, 0.3) + 2.0 * radius;
    c = obstacle_course(rng.next_u64(), m.spec);
  }
  m.env = std::make_unique<Environment>(c.outer, c.holes);
  m.narrowest = c.narrowest - 2.0 * radius;
  if (radius > 0.0) {
    // The largest part of the course shrunk by the radius, as an environment of its own.
    const ConfigurationSpace space(*m.env, radius);
    std::size_t largest = 0;
    for (std::size_t k = 1; k < space.part_count(); ++k) {
      if (space.part(k).area() > space.part(largest).area()) largest = k;
    }
    m.env = std::make_unique<Environment>(space.part(largest));
  }
  m.graph = std::make_unique<VisibilityGraph>(*m.env);
  for (const BoundaryEdge& e : m.env->boundary())
    m.boundary_length += distance(e.a, e.b);
  return m;
}

Vec2 point_on_boundary(const Environment& env, double length, RandomStream& rng) {
  double at = rng.uniform(0.0, length);
  for (const BoundaryEdge& e : env.boundary()) {
    const double l = distance(e.a, e.b);
    if (at <= l) return e.a + (at / l) * (e.b - e.a);
    at -= l;
  }
  return env.boundary().back().b;
}

// A point of the bounding box outside Ω (in an obstacle or a notch), if one is found.
std::optional<Vec2> point_outside(const Environment& env, RandomStream& rng) {
  const Box& b = env.bounds();
  for (int k = 0; k < 10000; ++k) {
    std::optional<Vec2> p;
    if (env.hole_count() > 0 && rng.bernoulli(0.8)) {
      // Thin obstacles are hard to hit from the whole box: aim at one.
      Box hb;
      for (Vec2 v : env.hole(rng.below(env.hole_count())))
        hb.add(v);
      p = Vec2{rng.uniform(hb.lo.x, hb.hi.x), rng.uniform(hb.lo.y, hb.hi.y)};
    } else {
      p = Vec2{rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y)};
    }
    if (!env.contains(*p)) return p;
  }
  return std::nullopt;
}

ContractResult run_case(const ContractSetup& setup, const ContractMap& map, std::uint64_t seed,
                        std::uint64_t index, bool record = false) {
  const Environment& env = *map.env;
  ContractResult res;
  res.seed = seed;
  res.index = index;
  res.reproducer = fmt::format(
      "covsim planner-contract --planner {} --range {} --noise {} --step {}{}{}{} --seed {} "
      "--case {}",
      setup.planner, number(setup.range), setup.noise_sigma, setup.step,
      setup.family == CaseFamily::combs ? " --family combs" : "",
      setup.radius > 0.0 ? fmt::format(" --radius {}", setup.radius) : "",
      setup.map == "given" ? "" : fmt::format(" --map {}", setup.map), seed, index);
  RandomStream rng(seed, index, "contract-case");
  const auto in_box = [&](const Box& b) {
    return Vec2{rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y)};
  };
  const double kind = setup.family == CaseFamily::combs ? 0.0 : rng.uniform01();
  if (setup.family == CaseFamily::combs) {
    res.start = in_box(map.below);
  } else {
    res.start = rng.bernoulli(0.15) ? point_on_boundary(env, map.boundary_length, rng)
                                    : uniform_point_by_rejection(env, rng);
  }
  if (setup.family == CaseFamily::combs) {
    res.goal = in_box(map.above);
  } else if (kind < 0.55) {
    res.goal = uniform_point_by_rejection(env, rng);
  } else if (kind < 0.8) {
    res.goal = point_outside(env, rng).value_or(uniform_point_by_rejection(env, rng));
  } else if (kind < 0.9) {
    res.goal = point_on_boundary(env, map.boundary_length, rng);
  } else {
    const Box& b = env.bounds();
    res.goal = {rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y)};
  }
  res.reachable = env.contains(res.goal);
  const Vec2 projection = res.reachable ? res.goal : env.closest_point(res.goal);
  const double tol = 1e-5 * env.diameter();

  const PlannerEntry* entry = planner_registry().find(setup.planner);
  PlannerConfig config;
  config.type = setup.planner;
  if (entry != nullptr && entry->contract.course_params)
    config.params = entry->contract.course_params(map.narrowest);
  if (setup.resolution) config.params.set("resolution", *setup.resolution);
  // Planners that offer no choice of map plan on what they sense, or on nothing.
  if (setup.map != "given" && entry != nullptr && find_param(entry->params, "map") != nullptr)
    config.params.set("map", setup.map);
  if (entry != nullptr) config.params = with_defaults(entry->params, config.params);
  const bool complete = setup.complete.value_or(entry == nullptr || entry->contract.complete);
  const SensorSpec sensor{setup.noise_sigma};
  std::unique_ptr<Planner> planner =
      setup.make ? setup.make(env, sensor) : planner_source(config, {env, sensor})();
  RandomStream noise(seed, index, "contract-noise");
  const auto max_steps =
      static_cast<std::size_t>(12.0 * (map.boundary_length + env.diameter()) / setup.step + 1000.0);

  const auto fail = [&](std::string what) {
    if (res.failure.empty()) res.failure = std::move(what);
  };
  planner->set_goal(res.goal);
  Vec2 x = res.start;
  std::vector<Vec2> walked{x};
  // TangentBug's loops closed when it decided the step from each position on.
  std::vector<std::uint32_t> loops;
  res.status = PlanStatus::moving;
  for (; res.steps < max_steps && res.status == PlanStatus::moving; ++res.steps) {
    SensorReading reading = sense(env, x, setup.range);
    if (setup.noise_sigma > 0.0)
      add_range_noise(reading, noise, setup.noise_sigma, env.tolerance());
    const PlanStep s = planner->step(reading, setup.step);
    if (distance(x, s.next) >
        setup.step * (1.0 + 1e-12) + std::max(1e-12, distance_rounding(x, s.next)))
      fail(fmt::format("step {}: proposed a step of {} m", res.steps, distance(x, s.next)));
    const Vec2 next = env.advance(x, s.next);
    // Into a wall the sensor showed (within range, or touching): the planner's own fault. A
    // wall beyond the range stops the motion as a real robot is stopped, on contact. (A
    // proposal that grazes a corner by a rounding error is not counted.)
    if (setup.noise_sigma == 0.0 && !env.segment_inside(x, s.next) &&
        distance(x, next) < std::max(setup.range, env.tolerance()) &&
        distance(s.next, env.closest_point(s.next)) > 1e-6 * env.diameter()) {
      fail(fmt::format("step {}: proposed a step into a sensed wall, ({}, {}) -> ({}, {})",
                       res.steps, x.x, x.y, s.next.x, s.next.y));
    }
    if (record) {
      res.path.push_back(x);
      const auto* bug = dynamic_cast<const TangentBug*>(planner.get());
      res.modes.emplace_back(bug != nullptr ? to_string(bug->mode()) : "");
    }
    res.length += distance(x, next);
    x = next;
    res.status = s.status;
    walked.push_back(x);
    const auto* bug = dynamic_cast<const TangentBug*>(planner.get());
    loops.push_back(bug != nullptr ? bug->loops() : 0);
  }
  // Back along its way for a step (beyond range noise's zigzags, 3σ either side).
  std::string turned;  // where it turned back, for the failure message
  for (std::size_t k : reversals(walked, setup.step + 6.0 * setup.noise_sigma,
                                 1e-6 * env.diameter() + 3.0 * setup.noise_sigma)) {
    ++res.reversals;
    if (loops[k] == 0) ++res.early_reversals;  // turned back before any loop closed
    turned += fmt::format("{}at step {} ({}, {}){}", turned.empty() ? "" : ", ", k, walked[k].x,
                          walked[k].y, loops[k] == 0 ? " before going round an obstacle" : "");
  }
  res.end = x;
  if (record) {
    res.path.push_back(x);
    res.rings = env.rings();
  }
  if (const auto* bug = dynamic_cast<const TangentBug*>(planner.get())) {
    res.episodes = bug->episodes().size();
    res.recoveries = bug->recoveries();
  }

  if (res.status == PlanStatus::moving) fail(fmt::format("no end within {} steps", max_steps));
  if (res.status == PlanStatus::reached && distance(x, res.goal) > tol)
    fail(fmt::format("reported reached {} m from the goal", distance(x, res.goal)));
  if (res.status == PlanStatus::projected) {
    if (res.reachable) fail("declared a goal in Ω unreachable (projected)");
    // With range noise, faces of Ω whose distances to the goal differ by less than the noise
    // cannot be told apart (a goal inside a thin wall): a robot's recorded closest point is
    // within 3σ of the closest distance, and it may settle within 3σ of that, so 6σ.
    const double want = distance(projection, res.goal), got = distance(x, res.goal);
    if (std::fabs(got - want) > tol + 6.0 * setup.noise_sigma || env.edges_at(x).empty())
      fail(fmt::format("projected to a point {} m from the goal; the projection is {} m away", got,
                       want));
  }
  const GeodesicPath path = map.graph->shortest_path(res.start, res.reachable ? res.goal : x);
  res.shortest = path.length;
  res.bound = INFINITY;
  if (entry != nullptr && entry->contract.path_bound && !setup.make) {
    const std::size_t turns = path.points.size() >= 2 ? path.points.size() - 2 : 0;
    res.bound = entry->contract.path_bound(PathBoundCase{*planner, env, config.params, res.shortest,
                                                         turns, res.reachable, setup.noise_sigma}) +
                tol;
  }
  if (complete) {
    if (res.reachable && res.status != PlanStatus::reached)
      fail(fmt::format("did not reach a reachable goal ({})", to_string(res.status)));
    if (!res.reachable && res.status != PlanStatus::projected)
      fail(fmt::format("did not settle at the projection of an unreachable goal ({})",
                       to_string(res.status)));
    if (res.length > res.bound)
      fail(fmt::format("path {} m exceeds its bound {} m (L* = {} m)", res.length, res.bound,
                       res.shortest));
    if (setup.noise_sigma == 0.0 && res.recoveries > 0)
      fail("a loop closed round an obstacle that does not enclose the goal");
  }
  // Range noise shows walls nearer or farther than they are, and a way along them that the
  // next reading contradicts: there the reversals are counted (ContractSummary::reversing),
  // not refused (docs/tangent_bug.md).
  if (entry != nullptr && entry->contract.keeps_direction && !setup.make &&
      setup.noise_sigma == 0.0) {
    if (res.early_reversals > 0 || res.reversals > 1)
      fail(fmt::format("walked back over its own ground: {}", turned));
  }
  if (!res.failure.empty()) {
    res.failure = fmt::format("{}: start ({}, {}), goal ({}, {}): {}", setup.label(), res.start.x,
                              res.start.y, res.goal.x, res.goal.y, res.failure);
  }
  return res;
}

void add(ContractSummary& s, const ContractResult& r) {
  ++s.cases;
  if (r.reachable) ++s.reachable;
  if (r.status == PlanStatus::reached) ++s.reached;
  if (r.status == PlanStatus::projected) ++s.projected;
  if (r.status == PlanStatus::stalled) ++s.stalled;
  s.recoveries += r.recoveries;
  if (r.reversals > 0) ++s.reversing;
  if (r.early_reversals > 0) ++s.early_reversing;
  if (r.status == PlanStatus::reached && r.shortest > 1e-9) {
    const double ratio = r.length / r.shortest;
    if (ratio > s.worst_ratio) {
      s.worst_ratio = ratio;
      s.worst_ratio_case = r.index;
    }
    s.mean_ratio += ratio;
    ++s.ratio_cases;
  }
  if (std::isfinite(r.bound) && r.bound > 0.0)
    s.worst_bound_use = std::max(s.worst_bound_use, r.length / r.bound);
  if (!r.failure.empty()) {
    ++s.failures;
    if (s.failed.size() < 20) s.failed.push_back(r);
  }
}

}  // namespace

std::string_view to_string(CaseFamily f) {
  return f == CaseFamily::combs ? "combs" : "courses";
}

std::string ContractSetup::label() const {
  return fmt::format("{} range={} noise={}{}{}{}", planner, number(range), noise_sigma,
                     family == CaseFamily::combs ? " combs" : "",
                     radius > 0.0 ? fmt::format(" radius={}", radius) : "",
                     map == "given" ? "" : " map=" + map);
}

ContractResult run_contract_case(const ContractSetup& setup, std::uint64_t seed,
                                 std::uint64_t index) {
  const ContractMap map = make_map(seed, index / kCasesPerMap, setup.family, setup.radius);
  return run_case(setup, map, seed, index, true);
}

ContractSummary run_contract(const ContractSetup& setup, std::uint64_t seed, std::uint64_t first,
                             std::uint64_t count, unsigned jobs,
                             const std::function<void(const ContractResult&)>& progress) {
  std::vector<ContractResult> results(count);
  // Workers take whole maps, so that each map is built once.
  const std::uint64_t first_group = first / kCasesPerMap;
  const std::uint64_t last_group = count == 0 ? first_group : (first + count - 1) / kCasesPerMap;
  std::atomic<std::uint64_t> next{first_group};
  std::mutex mutex;
  const auto work = [&] {
    for (std::uint64_t g = next++; g <= last_group && count > 0; g = next++) {
      const ContractMap map = make_map(seed, g, setup.family, setup.radius);
      for (std::uint64_t i = std::max(first, g * kCasesPerMap);
           i < std::min(first + count, (g + 1) * kCasesPerMap); ++i) {
        results[i - first] = run_case(setup, map, seed, i);
        if (progress) {
          const std::lock_guard<std::mutex> lock(mutex);
          progress(results[i - first]);
        }
      }
    }
  };
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < std::max(1u, jobs); ++t)
    threads.emplace_back(work);
  work();
  for (std::thread& t : threads)
    t.join();
  ContractSummary s;
  for (const ContractResult& r : results)
    add(s, r);
  if (s.ratio_cases > 0) s.mean_ratio /= static_cast<double>(s.ratio_cases);
  return s;
}

std::optional<std::string> contract_refusal(std::string_view planner) {
  planner_registry().at(planner);  // names the registered ones if unknown
  const Environment square({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {});
  if (make_planner(planner, square)->avoids_obstacles()) return std::nullopt;
  return "does not avoid obstacles (it drives through walls), and the contract checks planners "
         "that keep the robot in Ω";
}

RegistryContract run_registry_contract(const ContractSetup& setup, std::uint64_t seed,
                                       std::uint64_t first, std::uint64_t count, unsigned jobs) {
  RegistryContract out;
  for (const std::string& name : planner_registry().names()) {
    if (std::optional<std::string> why = contract_refusal(name)) {
      out.refused.emplace_back(name, std::move(*why));
      continue;
    }
    ContractSetup s = setup;
    s.planner = name;
    s.make = nullptr;
    out.checked.emplace_back(name, run_contract(s, seed, first, count, jobs));
  }
  return out;
}

RangeCurve range_curve(const ContractSetup& setup, const std::vector<double>& ranges,
                       std::uint64_t seed, std::uint64_t first, std::uint64_t count,
                       unsigned jobs) {
  const auto contact = std::find(ranges.begin(), ranges.end(), 0.0);
  if (contact == ranges.end()) throw std::invalid_argument("range_curve: ranges must hold 0");
  // Per range, per case: the path when reached with L* > 0, else NaN.
  std::vector<std::vector<double>> paths(ranges.size(), std::vector<double>(count, NAN));
  std::vector<double> shortest(count, NAN);
  RangeCurve curve;
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    ContractSetup s = setup;
    s.range = ranges[k];
    RangePoint point;
    point.range = ranges[k];
    std::mutex mutex;
    const ContractSummary summary =
        run_contract(s, seed, first, count, jobs, [&](const ContractResult& r) {
          if (r.status != PlanStatus::reached || !(r.shortest > 1e-9)) return;
          const std::lock_guard<std::mutex> lock(mutex);
          paths[k][r.index - first] = r.length;
          shortest[r.index - first] = r.shortest;
        });
    point.failures = summary.failures;
    curve.points.push_back(point);
  }
  const std::vector<double>& by_touch = paths[static_cast<std::size_t>(contact - ranges.begin())];
  for (std::uint64_t i = 0; i < count; ++i) {
    bool every = true;
    for (const std::vector<double>& p : paths)
      every = every && !std::isnan(p[i]);
    if (!every) continue;
    ++curve.cases;
    for (std::size_t k = 0; k < ranges.size(); ++k) {
      RangePoint& point = curve.points[k];
      point.mean_ratio += paths[k][i] / shortest[i];
      const double vs = paths[k][i] / by_touch[i];
      point.mean_vs_contact += vs;
      point.worst_vs_contact = std::max(point.worst_vs_contact, vs);
    }
  }
  for (RangePoint& point : curve.points) {
    if (curve.cases == 0) continue;
    point.mean_ratio /= static_cast<double>(curve.cases);
    point.mean_vs_contact /= static_cast<double>(curve.cases);
  }
  return curve;
}

}  // namespace covsim
