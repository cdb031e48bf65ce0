// covsim's half of scripts/compare-coveragecontrol, built against an installed covsim.
//
//   covsim_side world --sizes 32,100,1000 --seed 1 --out WORLD
//       KumarRobotics/CoverageControl's default world (bench/bench_world.hpp: the 1024 m
//       square, 32 bumps) and uniformly random generators for each N, as JSON that both
//       sides read, so that they start from the same numbers bit for bit.
//   covsim_side time --world WORLD --n N --iterations K --runs R --out FILE
//       K Lloyd iterations (the partition and every cell's summary) and R Lloyd runs to
//       convergence from the start generators, each in CPU time.
//   covsim_side reference --world WORLD --n N --out FILE
//       The start cells (clipped to the square) and their centroids by a long double
//       integration that shares nothing with covsim's moments: strips in y, each strip's
//       moments in x in closed form, per bump.
#include <time.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bench_world.hpp"
#include "geometry/gaussian_mixture_density.hpp"
#include "geometry/voronoi_partition.hpp"

namespace {

using namespace covsim;
using nlohmann::json;
using LD = long double;

// CPU time of the whole process: what both sides are compared in.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// --key value pairs after the command.
std::map<std::string, std::string> options(int argc, char** argv) {
  std::map<std::string, std::string> out;
  for (int i = 2; i < argc; i += 2) {
    const std::string key = argv[i];
    if (key.rfind("--", 0) != 0 || i + 1 >= argc)
      throw std::invalid_argument("expected --key value, got '" + key + "'");
    out[key.substr(2)] = argv[i + 1];
  }
  return out;
}

const std::string& need(const std::map<std::string, std::string>& opt, const std::string& key) {
  const auto it = opt.find(key);
  if (it == opt.end()) throw std::invalid_argument("missing --" + key);
  return it->second;
}

long number(const std::string& text) {
  long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    throw std::invalid_argument("not a number: '" + text + "'");
  return v;
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  return json::parse(in);
}

void write_json(const std::string& path, const json& j) {
  std::ofstream out(path);
  out << j.dump() << '\n';
  if (!out) throw std::runtime_error("cannot write " + path);
}

Vec2 point(const json& p) {
  return {p.at(0).get<double>(), p.at(1).get<double>()};
}

// The world as the JSON gives it: the square, the bumps, the start generators for n.
struct World {
  double side = 0;
  std::vector<GaussianComponent> bumps;
  std::vector<Vec2> start;
};

World read_world(const std::string& path, long n) {
  const json j = read_json(path);
  World w;
  w.side = j.at("side").get<double>();
  for (const json& b : j.at("bumps"))
    w.bumps.push_back(
        {point(b.at("mean")), b.at("sigma").get<double>(), b.at("weight").get<double>()});
  const json& g = j.at("generators").at(std::to_string(n));
  for (const json& p : g)
    w.start.push_back(point(p));
  return w;
}

Environment square(double side) {
  return Environment({{0, 0}, {side, 0}, {side, side}, {0, side}}, {});
}

json points_json(const std::vector<Vec2>& pts) {
  json out = json::array();
  for (Vec2 p : pts)
    out.push_back({p.x, p.y});
  return out;
}

int world_command(const std::map<std::string, std::string>& opt) {
  const auto seed = static_cast<std::uint64_t>(number(need(opt, "seed")));
  const Environment& env = bench::peer_environment();
  const Box box = env.bounds();
  if (box.lo.x != 0 || box.lo.y != 0 || box.hi.x != box.hi.y)
    throw std::runtime_error("the peer world is expected to be a square at the origin");
  json j;
  j["side"] = box.hi.x;
  j["bumps"] = json::array();
  for (const GaussianComponent& b : bench::peer_bumps())
    j["bumps"].push_back(
        {{"mean", {b.mean.x, b.mean.y}}, {"sigma", b.sigma}, {"weight", b.weight}});
  j["seed"] = seed;
  std::string sizes = need(opt, "sizes");
  for (std::size_t at = 0; at <= sizes.size();) {
    const std::size_t comma = std::min(sizes.find(',', at), sizes.size());
    const long n = number(sizes.substr(at, comma - at));
    if (n < 2) throw std::invalid_argument("sizes must be at least 2");
    j["generators"][std::to_string(n)] =
        points_json(bench::random_points_in(env, static_cast<std::size_t>(n), seed));
    at = comma + 1;
  }
  write_json(need(opt, "out"), j);
  return 0;
}

// One Lloyd step: the partition of g, every cell's summary; g moves to the centroids.
// Returns the largest move.
double lloyd_step(const CellIntegrator& integrator, std::vector<Vec2>& g, double& sink) {
  const VoronoiPartition partition(integrator, g);
  double move = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const CellSummary s = partition.summary(i);
    sink += s.cost;
    move = std::max(move, distance(s.centroid, g[i]));
    g[i] = s.centroid;
  }
  return move;
}

int time_command(const std::map<std::string, std::string>& opt) {
  const long n = number(need(opt, "n"));
  const long iterations = number(need(opt, "iterations")), runs = number(need(opt, "runs"));
  const double tolerance = 1e-3;
  const long max_iterations = 100;
  const World w = read_world(need(opt, "world"), n);

  // Setup, not counted in the iterations (the peer's counterpart is its raster map).
  double t0 = cpu_seconds();
  const Environment env = square(w.side);
  const GaussianMixtureDensity density(w.bumps, 0.0);
  const CellIntegrator integrator(env, density);
  const double setup = cpu_seconds() - t0;

  double sink = 0;
  json out;
  out["setup_cpu_s"] = setup;
  out["iteration_cpu_s"] = json::array();
  std::vector<Vec2> centroids(w.start.size());
  for (long k = 0; k < iterations; ++k) {
    t0 = cpu_seconds();
    const VoronoiPartition partition(integrator, w.start);
    for (std::size_t i = 0; i < w.start.size(); ++i) {
      const CellSummary s = partition.summary(i);
      sink += s.cost;
      centroids[i] = s.centroid;
    }
    out["iteration_cpu_s"].push_back(cpu_seconds() - t0);
  }
  out["centroids"] = points_json(centroids);

  out["runs"] = json::array();
  for (long r = 0; r < runs; ++r) {
    std::vector<Vec2> g = w.start;
    long steps = 0;
    double move = std::numeric_limits<double>::infinity();
    t0 = cpu_seconds();
    while (steps < max_iterations && !(move < tolerance)) {
      move = lloyd_step(integrator, g, sink);
      ++steps;
    }
    const double t = cpu_seconds() - t0;
    out["runs"].push_back({{"cpu_s", t}, {"iterations", steps}, {"last_move", move}});
  }
  out["sink"] = sink;  // keeps the work observable
  write_json(need(opt, "out"), out);
  return 0;
}

// ---------------------------------------------------------------------------------------
// The reference: long double, its own Gauss-Legendre rule, nothing of covsim's moments.

constexpr LD kPi = 3.14159265358979323846264338327950288L;

struct Rule {
  std::vector<LD> nodes, weights;  // on [0, 1]
};

// 32-point Gauss-Legendre by Newton's method on P_32, in long double.
const Rule& legendre() {
  static const Rule rule = [] {
    constexpr int m = 32;
    Rule r;
    for (int i = 1; i <= m; ++i) {
      LD x = std::cos(kPi * (i - 0.25L) / (m + 0.5L)), dp = 0;
      for (int it = 0; it < 100; ++it) {
        LD p0 = 1, p1 = x;
        for (int k = 2; k <= m; ++k) {
          const LD p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = m * (x * p1 - p0) / (x * x - 1);
        const LD dx = p1 / dp;
        x -= dx;
        if (std::fabs(dx) < 1e-19L) break;
      }
      r.nodes.push_back((1 - x) / 2);
      r.weights.push_back(1 / ((1 - x * x) * dp * dp));  // 2 / (...) halved for [0, 1]
    }
    return r;
  }();
  return rule;
}

LD normal_cdf(LD x) {
  return 0.5L * std::erfc(-x / std::sqrt(2.0L));
}
LD normal_pdf(LD x) {
  return std::exp(-0.5L * x * x) / std::sqrt(2.0L * kPi);
}
// P(a < X < b) for a standard normal X, in relative precision in either tail.
LD normal_mass(LD a, LD b) {
  return a > 0 ? normal_cdf(-a) - normal_cdf(-b) : normal_cdf(b) - normal_cdf(a);
}

struct LVec {
  LD x = 0, y = 0;
};
struct StdMoments {
  LD mass = 0, fx = 0, fy = 0;  // of the standard normal density, about its mean
};

// A convex polygon (in units of sigma about the mean) by strips in y between its vertices'
// heights; inside each, pieces short enough that the integrand's logarithm changes by about
// `step` at most across one (its slope is bounded by |y| and by |x| times the edges' slopes
// in x), each by 32-point Gauss-Legendre, every strip's x-moments in closed form.
StdMoments strips(const std::vector<LVec>& poly, LD step) {
  const Rule& q = legendre();
  std::vector<LD> ys;
  for (const LVec& p : poly)
    ys.push_back(p.y);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  const auto span = [&](LD y, LD& lo, LD& hi) {
    lo = INFINITY;
    hi = -INFINITY;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const LVec a = poly[i], b = poly[(i + 1) % poly.size()];
      if (a.y == b.y || y < std::min(a.y, b.y) || y > std::max(a.y, b.y)) continue;
      const LD x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  };
  StdMoments out;
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
    const LD y0 = ys[k], y1 = ys[k + 1], h = y1 - y0;
    LD lo0, hi0, lo1, hi1;
    span(y0, lo0, hi0);
    span(y1, lo1, hi1);
    const LD rate = std::max(std::fabs(y0), std::fabs(y1)) +
                    std::max(std::fabs(lo0), std::fabs(lo1)) * std::fabs(lo1 - lo0) / h +
                    std::max(std::fabs(hi0), std::fabs(hi1)) * std::fabs(hi1 - hi0) / h;
    const int n = std::max(1, static_cast<int>(std::ceil(h * (1 + rate) / step)));
    const LD len = h / n;
    for (int p = 0; p < n; ++p) {
      for (std::size_t i = 0; i < q.nodes.size(); ++i) {
        const LD y = y0 + len * (p + q.nodes[i]);
        LD lo, hi;
        span(y, lo, hi);
        if (!(hi > lo)) continue;
        const LD w = len * q.weights[i] * normal_pdf(y), m = normal_mass(lo, hi);
        out.mass += w * m;
        out.fx += w * (normal_pdf(lo) - normal_pdf(hi));
        out.fy += w * y * m;
      }
    }
  }
  return out;
}

struct Centroid {
  LD mass = 0, x = 0, y = 0;
};

// The mixture Σ weight · exp(-|x - mean|² / (2 sigma²)) over a polygon: each bump's
// standard-normal moments scaled back (mass 2π σ² weight per unit of probability).
Centroid reference_centroid(const std::vector<Vec2>& cell,
                            const std::vector<GaussianComponent>& bumps, LD step) {
  LD mass = 0, fx = 0, fy = 0;
  for (const GaussianComponent& b : bumps) {
    const LD s = b.sigma;
    std::vector<LVec> q;
    for (Vec2 p : cell)
      q.push_back({(LD(p.x) - b.mean.x) / s, (LD(p.y) - b.mean.y) / s});
    const StdMoments m = strips(q, step);
    const LD scale = LD(b.weight) * 2 * kPi * s * s;
    mass += scale * m.mass;
    fx += scale * (b.mean.x * m.mass + s * m.fx);
    fy += scale * (b.mean.y * m.mass + s * m.fy);
  }
  return {mass, fx / mass, fy / mass};
}

int reference_command(const std::map<std::string, std::string>& opt) {
  const long n = number(need(opt, "n"));
  const World w = read_world(need(opt, "world"), n);
  const Environment env = square(w.side);
  const GaussianMixtureDensity density(w.bumps, 0.0);
  const CellIntegrator integrator(env, density);
  const VoronoiPartition partition(integrator, w.start);
  const std::vector<HalfPlane> sides{
      {{1, 0}, w.side}, {{-1, 0}, 0}, {{0, 1}, w.side}, {{0, -1}, 0}};
  constexpr LD step = 1.0L;
  // The rule's own check: the first cells again with pieces four times shorter.
  const std::size_t checked = std::min<std::size_t>(partition.size(), 16);
  json out;
  out["centroids"] = json::array();
  out["areas"] = json::array();
  double self_check = 0;
  for (std::size_t i = 0; i < partition.size(); ++i) {
    ConvexPolygon cell(partition.cell(i).begin(), partition.cell(i).end()), tmp;
    for (const HalfPlane& h : sides) {
      clip(cell, h, tmp);
      cell.swap(tmp);
    }
    if (cell.size() < 3)
      throw std::runtime_error("an empty cell at generator " + std::to_string(i));
    const Centroid c = reference_centroid(cell, w.bumps, step);
    if (i < checked) {
      const Centroid fine = reference_centroid(cell, w.bumps, step / 4);
      self_check =
          std::max(self_check, static_cast<double>(std::hypot(c.x - fine.x, c.y - fine.y)));
    }
    out["centroids"].push_back({static_cast<double>(c.x), static_cast<double>(c.y)});
    out["areas"].push_back(std::fabs(signed_area(cell)));
  }
  out["self_check_m"] = self_check;
  write_json(need(opt, "out"), out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2)
      throw std::invalid_argument("usage: covsim_side world|time|reference --key value ...");
    const std::string command = argv[1];
    const auto opt = options(argc, argv);
    if (command == "world") return world_command(opt);
    if (command == "time") return time_command(opt);
    if (command == "reference") return reference_command(opt);
    throw std::invalid_argument("unknown command '" + command + "'");
  } catch (const std::exception& e) {
    std::cerr << "covsim_side: " << e.what() << '\n';
    return 1;
  }
}
