#include "scenarios/random_environment.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/random_stream.hpp"
#include "geometry/environment.hpp"
#include "robot/coverage_config.hpp"
#include "scenarios/run_limits.hpp"

namespace covsim {

namespace {
struct Circle {
  Vec2 centre;
  double radius;
};

// Whether a disc lies inside the polygon with `clearance` to spare.
bool disc_inside(const std::vector<Vec2>& ring, const Circle& c, double clearance) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[j], b = ring[i];
    if (distance(c.centre, project_to_segment(c.centre, a, b).point) < c.radius + clearance)
      return false;
    if ((a.y > c.centre.y) != (b.y > c.centre.y) &&
        c.centre.x < a.x + (c.centre.y - a.y) * (b.x - a.x) / (b.y - a.y))
      inside = !inside;
  }
  return inside;
}

nlohmann::ordered_json to_json(const std::vector<Vec2>& ring) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (Vec2 p : ring)
    out.push_back({p.x, p.y});
  return out;
}
}  // namespace

nlohmann::ordered_json random_environment(const RandomEnvironmentSpec& spec) {
  if (spec.outer_vertices < 3 || spec.outer_vertices > 1000)
    throw std::invalid_argument("the outer ring needs 3 to 1000 vertices");
  if (spec.robots < 1 || spec.robots > 100000)
    throw std::invalid_argument("a scenario needs 1 to 100000 robots");
  if (spec.holes > 100) throw std::invalid_argument("at most 100 holes");
  if (!(spec.size > 0.0) || !std::isfinite(spec.size))
    throw std::invalid_argument("the size must be a positive number");
  const double two_pi = 2.0 * std::numbers::pi;
  const double s = spec.size;
  const Vec2 centre{s / 2, s / 2};
  RandomStream outer_rng(spec.seed, 0, "random-environment-outer");
  std::vector<Vec2> outer;
  const double sector = two_pi / spec.outer_vertices;
  for (std::uint32_t k = 0; k < spec.outer_vertices; ++k) {
    const double angle = (k + outer_rng.uniform(-0.35, 0.35)) * sector;
    const double radius = outer_rng.uniform(0.55, 1.0) * 0.5 * s;
    outer.push_back(centre + radius * Vec2{std::cos(angle), std::sin(angle)});
  }
  // Holes: convex polygons in circles clear of the outer ring and of each other.
  RandomStream hole_rng(spec.seed, 0, "random-environment-holes");
  const double clearance = 0.04 * s;
  std::vector<Circle> circles;
  std::vector<std::vector<Vec2>> holes;
  for (int attempt = 0; attempt < 200 && holes.size() < spec.holes; ++attempt) {
    const Circle c{{hole_rng.uniform(0.1, 0.9) * s, hole_rng.uniform(0.1, 0.9) * s},
                   hole_rng.uniform(0.05, 0.13) * s};
    bool fits = disc_inside(outer, c, clearance);
    for (const Circle& o : circles)
      fits = fits && distance(c.centre, o.centre) >= c.radius + o.radius + clearance;
    if (!fits) continue;
    const auto n = static_cast<std::uint32_t>(3 + hole_rng.next_u64() % 4);
    std::vector<Vec2> ring;
    const double phase = hole_rng.uniform(0.0, two_pi);
    for (std::uint32_t k = 0; k < n; ++k) {
      const double angle = phase + (k + hole_rng.uniform(-0.25, 0.25)) * two_pi / n;
      ring.push_back(c.centre + c.radius * Vec2{std::cos(angle), std::sin(angle)});
    }
    circles.push_back(c);
    holes.push_back(std::move(ring));
  }
  const Environment env(outer, holes);  // validates: throws GeometryError if anything is off
  // Robots: points of Ω away from ∂Ω and from each other, by dart throwing. The distance
  // kept is 2% of the size, or for many robots half the spacing of N robots at constant
  // density, sqrt(area / N) / 2 (dart throwing fills about half the plane with discs of
  // that spacing's diameter); a grid of cells that side long finds the near robots.
  RandomStream robot_rng(spec.seed, 0, "random-environment-robots");
  std::vector<Vec2> robots;
  const double apart =
      std::min(0.02 * s, 0.5 * std::sqrt(env.area() / static_cast<double>(spec.robots)));
  const auto cells = static_cast<std::size_t>(std::ceil(s / apart));
  std::vector<std::vector<std::uint32_t>> grid(cells * cells);
  const auto cell_of = [&](double v) {
    return std::min(cells - 1, static_cast<std::size_t>(std::max(0.0, v / apart)));
  };
  const std::uint64_t attempts = 100000 + 200 * static_cast<std::uint64_t>(spec.robots);
  for (std::uint64_t attempt = 0; attempt < attempts && robots.size() < spec.robots; ++attempt) {
    const Vec2 p{robot_rng.uniform(0.0, s), robot_rng.uniform(0.0, s)};
    if (!env.contains(p)) continue;
    const std::size_t cx = cell_of(p.x), cy = cell_of(p.y);
    bool ok = true;
    for (std::size_t x = cx > 0 ? cx - 1 : 0; ok && x <= std::min(cells - 1, cx + 1); ++x)
      for (std::size_t y = cy > 0 ? cy - 1 : 0; ok && y <= std::min(cells - 1, cy + 1); ++y)
        for (std::uint32_t q : grid[x * cells + y])
          ok = ok && distance(p, robots[q]) >= apart;
    for (const BoundaryEdge& e : env.boundary())
      ok = ok && distance(p, project_to_segment(p, e.a, e.b).point) >= apart;
    if (!ok) continue;
    grid[cx * cells + cy].push_back(static_cast<std::uint32_t>(robots.size()));
    robots.push_back(p);
  }
  if (robots.size() < spec.robots)
    throw std::invalid_argument("could not place the robots: the environment is too narrow");
  nlohmann::ordered_json out;
  out["environment"]["outer"] = to_json(outer);
  out["environment"]["holes"] = nlohmann::ordered_json::array();
  for (const auto& h : holes)
    out["environment"]["holes"].push_back(to_json(h));
  out["density"] = {{"type", "uniform"}};
  out["robots"]["positions"] = to_json(robots);
  out["seed"] = spec.seed;
  // Room to cross the environment several times at the default speed (0.1 m/s).
  const double max_time = 300.0 * s;
  out["convergence"] = {{"max_time", max_time}};
  // Many robots: trajectory rows 1, 2 or 5 times a power of ten seconds apart, so that the
  // file stays under half the default limits.trajectory_rows.
  const double rows_per_robot =
      0.5 * RunLimits{}.trajectory_rows / static_cast<double>(spec.robots);
  if (max_time / CoverageConfig{}.loop2_period.seconds() > rows_per_robot) {
    const double wanted = max_time / rows_per_robot;
    double period = std::pow(10.0, std::floor(std::log10(wanted)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
      if (m * period >= wanted) {
        period *= m;
        break;
      }
    }
    out["recording"] = {{"trajectory_period", period}};
  }
  return out;
}

}  // namespace covsim
