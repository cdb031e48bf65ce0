#include "analysis/contract/law_contract.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/random_stream.hpp"
#include "geometry/placement.hpp"
#include "geometry/uniform_density.hpp"
#include "geometry/voronoi_partition.hpp"
#include "robot/coverage_law_registry.hpp"
#include "robot/generator_state.hpp"
#include "robot/ideal_view.hpp"
#include "scenarios/obstacle_course.hpp"

namespace covsim {

namespace {

// Andrew's monotone chain: the convex hull, counter-clockwise, without collinear points.
std::vector<Vec2> convex_hull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  const auto turn = [](Vec2 o, Vec2 a, Vec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0)
      --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(h[k - 2], h[k - 1], p[i]) <= 0)
      --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

Environment make_environment(std::uint64_t seed, std::uint64_t index, bool convex) {
  RandomStream rng(seed, index, "law-contract-map");
  if (convex) {
    // The hull of random points in a random box: wide enough to hold cells of every size.
    for (;;) {
      const double w = rng.uniform(1.0, 6.0), h = rng.uniform(1.0, 6.0);
      std::vector<Vec2> points(4 + rng.below(8));
      for (Vec2& q : points)
        q = {rng.uniform(0.0, w), rng.uniform(0.0, h)};
      std::vector<Vec2> hull = convex_hull(points);
      if (hull.size() >= 3) return Environment(hull, {});
    }
  }
  ObstacleCourseSpec spec;
  spec.width = rng.uniform(4.0, 7.0);
  spec.height = rng.uniform(4.0, 7.0);
  spec.obstacles = static_cast<std::uint32_t>(1 + rng.below(4));
  spec.clearance = 0.2;
  spec.notches = static_cast<std::uint32_t>(rng.below(3));
  const ObstacleCourse c = obstacle_course(rng.next_u64(), spec);
  return Environment(c.outer, c.holes);
}

double segment_distance(Vec2 x, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double l2 = dot(d, d);
  const double s = l2 > 0.0 ? std::clamp(dot(x - a, d) / l2, 0.0, 1.0) : 0.0;
  return distance(x, a + s * d);
}

bool finite(Vec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

// Lloyd's iterations from `p`, computed here from partitions alone, until no generator
// moves by more than `tol` (or 500 iterations); returns the largest move left.
double centroidal(const CellIntegrator& integrator, std::vector<Vec2>& p, double tol) {
  double residual = INFINITY;
  for (int k = 0; k < 500 && residual > tol; ++k) {
    const VoronoiPartition partition(integrator, p, VoronoiPartition::Coincident::split);
    residual = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 c = partition.summary(i).centroid;
      residual = std::max(residual, distance(c, p[i]));
      p[i] = c;
    }
  }
  const VoronoiPartition last(integrator, p, VoronoiPartition::Coincident::split);
  residual = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    residual = std::max(residual, distance(last.summary(i).centroid, p[i]));
  return residual;
}

struct Case {
  const LawEntry& entry;
  LawContractResult& res;
  double worst_cost_rise = -INFINITY;
};

void run_case(Case& c) {
  LawContractResult& res = c.res;
  const LawEntry& entry = c.entry;
  res.convex = res.index % 2 == 0;
  const Environment env = make_environment(res.seed, res.index, res.convex);
  const UniformDensity density;
  const CellIntegrator integrator(env, density);
  const Params params = with_defaults(entry.params, Params{});
  if (entry.check) entry.check(env, params);
  const std::unique_ptr<CoverageLaw> law = entry.make(LawContext{env, density, integrator}, params);
  const Generators kind = law->generators();
  const double tiny = 1e-9 * env.diameter();

  RandomStream rng(res.seed, res.index, "law-contract-case");
  std::vector<Vec2> g(2 + rng.below(7));
  for (Vec2& p : g) {
    // Virtual generators may stand outside Ω (an obstacle boundary Voronoi region's).
    if (kind == Generators::virtual_generators && rng.bernoulli(0.2)) {
      const Box& b = env.bounds();
      p = {rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y)};
    } else {
      p = uniform_point_by_rejection(env, rng);
    }
  }
  res.robots = g.size();
  const auto fail = [&](std::string what) {
    if (res.failure.empty()) res.failure = std::move(what);
  };
  const auto robot = [&](std::uint32_t i, Vec2 p) {
    Robot r;
    r.id = i;
    r.virtual_generator = r.virtual_target = r.real_target = p;
    r.position = env.contains(p) ? p : env.closest_point(p);
    return r;
  };
  // Every robot's target from the shared partition, checked against its own cell's. One
  // state for the case, whose versions tell the law's caches that the points moved.
  GeneratorState state(integrator, g);
  const IdealView view(state);
  const auto targets = [&](const std::vector<Vec2>& points) {
    for (std::uint32_t i = 0; i < points.size(); ++i)
      state.move(kind, i, points[i]);
    std::vector<Vec2> t(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) {
      const Robot r = robot(i, points[i]);
      t[i] = law->target(r, view.knowledge(i, kind));
      const Vec2 alone = law->target(r, Knowledge{points, i, kind, nullptr, std::nullopt, nullptr});
      if (!finite(t[i]) || !finite(alone))
        fail(fmt::format("robot {}: a target that is not finite", i));
      else if (distance(t[i], alone) > tiny)
        fail(fmt::format("robot {}: its own cell gives ({}, {}), the shared partition ({}, {})", i,
                         alone.x, alone.y, t[i].x, t[i].y));
    }
    return t;
  };
  const std::vector<Vec2> t = targets(g);
  const VoronoiPartition partition(integrator, g, VoronoiPartition::Coincident::split);

  // From part of the others only.
  for (std::uint32_t i = 0; i < g.size(); ++i) {
    std::vector<Vec2> known;
    std::size_t self = 0;
    for (std::uint32_t j = 0; j < g.size(); ++j) {
      if (j == i) self = known.size();
      if (j == i || rng.bernoulli(0.5)) known.push_back(g[j]);
    }
    const Vec2 x =
        law->target(robot(i, g[i]), Knowledge{known, self, kind, nullptr, std::nullopt, nullptr});
    if (!finite(x))
      fail(fmt::format("robot {}: a target that is not finite from {} of {} robots", i,
                       known.size(), g.size()));
    if (entry.contract.lloyd && finite(x)) {
      const VoronoiPartition mine(integrator, known, VoronoiPartition::Coincident::split);
      const Vec2 want = mine.summary(self).centroid;
      if (distance(x, want) > tiny)
        fail(fmt::format("robot {} knowing {} of {}: target ({}, {}), its cell's centroid ({}, {})",
                         i, known.size(), g.size(), x.x, x.y, want.x, want.y));
    }
  }

  if (entry.contract.lloyd) {
    for (std::size_t i = 0; i < g.size(); ++i) {
      const Vec2 want = partition.summary(i).centroid;
      if (distance(t[i], want) > tiny)
        fail(fmt::format("robot {}: target ({}, {}), its cell's centroid ({}, {})", i, t[i].x,
                         t[i].y, want.x, want.y));
    }
    const double before = partition.cost();
    const double after =
        VoronoiPartition(integrator, t, VoronoiPartition::Coincident::split).cost();
    c.worst_cost_rise = std::max(c.worst_cost_rise, after / before - 1.0);
    if (after > before * (1.0 + 1e-9))
      fail(
          fmt::format("a step of every robot to its target raised H from {} to {}", before, after));
  }
  std::optional<double> tol;
  if (entry.contract.lloyd) tol = tiny;
  if (res.convex && entry.contract.convex_step_tolerance) {
    const double step_tol = entry.contract.convex_step_tolerance(env, params);
    tol = std::max(tol.value_or(0.0), step_tol);
    for (std::size_t i = 0; i < g.size(); ++i) {
      const Vec2 c_i = partition.summary(i).centroid;
      const double off = segment_distance(t[i], g[i], c_i);
      if (off > step_tol)
        fail(
            fmt::format("robot {}: target ({}, {}) lies {} m off the way from ({}, {}) to its "
                        "cell's centroid ({}, {}), more than {} m",
                        i, t[i].x, t[i].y, off, g[i].x, g[i].y, c_i.x, c_i.y, step_tol));
    }
  }
  if (!tol) return;
  // At rest at a centroidal configuration: every target on its generator, and the law says
  // so itself.
  std::vector<Vec2> star = g;
  const double residual = centroidal(integrator, star, tiny);
  const std::vector<Vec2> rest = targets(star);
  for (std::uint32_t i = 0; i < star.size(); ++i) {
    const double moved = distance(rest[i], star[i]);
    Robot r = robot(i, star[i]);
    r.virtual_target = rest[i];
    const double allowed = *tol + residual;
    if (moved > allowed)
      fail(
          fmt::format("at a centroidal configuration (Lloyd residual {} m) robot {}'s target "
                      "moves {} m, more than {} m",
                      residual, i, moved, allowed));
    else if (!law->at_rest(r, Tolerances{allowed, allowed}))
      fail(fmt::format("at a centroidal configuration robot {} on its target is not at rest", i));
  }
}

}  // namespace

namespace {
LawContractResult one_case(const LawEntry& entry, std::uint64_t seed, std::uint64_t index,
                           double& worst_cost_rise) {
  LawContractResult res;
  res.seed = seed;
  res.index = index;
  res.reproducer = fmt::format("law_contract_case(\"{}\", {}, {})", entry.name, seed, index);
  Case c{entry, res};
  try {
    run_case(c);
  } catch (const std::exception& e) {
    res.failure = fmt::format("threw: {}", e.what());
  }
  worst_cost_rise = std::max(worst_cost_rise, c.worst_cost_rise);
  if (!res.failure.empty())
    res.failure = fmt::format("{} case {} ({}, {} robots): {}", entry.name, index,
                              res.convex ? "convex" : "obstacle course", res.robots, res.failure);
  return res;
}
}  // namespace

LawContractResult law_contract_case(const std::string& law, std::uint64_t seed,
                                    std::uint64_t index) {
  double worst = -INFINITY;
  return one_case(coverage_law_registry().at(law), seed, index, worst);
}

LawContractSummary run_law_contract(const std::string& law, std::uint64_t seed, std::uint64_t first,
                                    std::uint64_t count) {
  const LawEntry& entry = coverage_law_registry().at(law);
  LawContractSummary s;
  s.law = law;
  s.checks = {"finite", "own cell"};
  if (entry.contract.lloyd) s.checks.insert(s.checks.end(), {"centroid", "cost", "at rest"});
  if (entry.contract.convex_step_tolerance) {
    s.checks.push_back("convex step");
    if (!entry.contract.lloyd) s.checks.push_back("at rest");
  }
  double worst = -INFINITY;
  for (std::uint64_t i = first; i < first + count; ++i) {
    LawContractResult res = one_case(entry, seed, i, worst);
    ++s.cases;
    if (!res.failure.empty()) {
      ++s.failures;
      if (s.failed.size() < 20) s.failed.push_back(std::move(res));
    }
  }
  if (entry.contract.lloyd) s.worst_cost_rise = worst;
  return s;
}

std::vector<LawContractSummary> run_registry_law_contract(std::uint64_t seed, std::uint64_t first,
                                                          std::uint64_t count) {
  std::vector<LawContractSummary> out;
  for (const std::string& name : coverage_law_registry().names())
    out.push_back(run_law_contract(name, seed, first, count));
  return out;
}

}  // namespace covsim
