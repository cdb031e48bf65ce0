// KumarRobotics/CoverageControl's half of scripts/compare-coveragecontrol, compiled with the
// peer's CPU sources (C++17, no CUDA) and nothing of covsim:
//
//   coveragecontrol_side --world WORLD --n N --truncation T --iterations K --runs R --out FILE
//
// The world written by covsim_side becomes the peer's WorldIDF of circular bivariate
// normals on its raster (pWorldMapSize cells of pResolution metres, built once and not
// counted). An iteration is what the peer's own CentralizedCVT does per step: a Voronoi
// construction (cells, masses, centroids) and reading its cells; a run repeats it, moving
// every site to its centroid, until the largest move is below 1e-3 m or 100 iterations.
#include <omp.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "CoverageControl/bivariate_normal_distribution.h"
#include "CoverageControl/parameters.h"
#include "CoverageControl/typedefs.h"
#include "CoverageControl/voronoi.h"
#include "CoverageControl/world_idf.h"

namespace {

namespace cc = CoverageControl;
using nlohmann::json;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::map<std::string, std::string> options(int argc, char** argv) {
  std::map<std::string, std::string> out;
  for (int i = 1; i < argc; i += 2) {
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

json points_json(const cc::PointVector& pts) {
  json out = json::array();
  for (const cc::Point2& p : pts)
    out.push_back({p.x(), p.y()});
  return out;
}

double polygon_area(const cc::PointVector& poly) {
  double twice = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const cc::Point2& a = poly[i];
    const cc::Point2& b = poly[(i + 1) % poly.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return std::fabs(twice) / 2;
}

int run(const std::map<std::string, std::string>& opt) {
  const std::size_t n = std::stoul(need(opt, "n"));
  const double truncation = std::stod(need(opt, "truncation"));
  const long iterations = std::stol(need(opt, "iterations")), runs = std::stol(need(opt, "runs"));
  const double tolerance = 1e-3;
  const long max_iterations = 100;

  std::ifstream in(need(opt, "world"));
  if (!in) throw std::runtime_error("cannot read " + need(opt, "world"));
  const json world = json::parse(in);

  // The peer's defaults (parameters.h) but the truncation; the square must be its map.
  cc::Parameters params;
  params.pTruncationBND = truncation;
  const double side = world.at("side").get<double>();
  if (side != params.pWorldMapSize * params.pResolution)
    throw std::runtime_error("the world's square is not the peer's default map");
  const cc::Point2 map_size(params.pWorldMapSize, params.pWorldMapSize);

  // covsim's bump is weight · exp(-|x - mean|² / (2 sigma²)); the peer's is scale times the
  // normalised density (a pixel holds scale times its probability, IntegrateQuarterPlane),
  // so scale = weight · 2π sigma². The peer then rescales the map so that its largest pixel
  // is pNorm: one factor on the whole density, which no centroid sees.
  cc::WorldIDF idf(params);
  for (const json& b : world.at("bumps")) {
    const double sigma = b.at("sigma").get<double>(), weight = b.at("weight").get<double>();
    const cc::Point2 mean(b.at("mean").at(0).get<double>(), b.at("mean").at(1).get<double>());
    idf.AddNormalDistribution(
        cc::BivariateNormalDistribution(mean, sigma, weight * 2 * M_PI * sigma * sigma));
  }
  double t0 = cpu_seconds();
  idf.GenerateMap();
  const double setup = cpu_seconds() - t0;
  const cc::MapType& map = idf.GetWorldMap();

  cc::PointVector start;
  for (const json& p : world.at("generators").at(std::to_string(n)))
    start.emplace_back(p.at(0).get<double>(), p.at(1).get<double>());

  double sink = 0;
  json out;
  out["setup_cpu_s"] = setup;
  out["omp_thread_limit"] = omp_get_thread_limit();
  out["iteration_cpu_s"] = json::array();
  cc::PointVector centroids(n);
  std::vector<double> areas(n);
  for (long k = 0; k < iterations; ++k) {
    t0 = cpu_seconds();
    const cc::Voronoi voronoi(start, map, map_size, params.pResolution);
    const auto cells = voronoi.GetVoronoiCells();
    for (std::size_t i = 0; i < n; ++i) {
      sink += cells[i].mass();
      centroids[i] = cells[i].centroid();
    }
    out["iteration_cpu_s"].push_back(cpu_seconds() - t0);
    for (std::size_t i = 0; i < n; ++i)
      areas[i] = polygon_area(cells[i].cell);
  }
  out["centroids"] = points_json(centroids);
  out["areas"] = areas;

  out["runs"] = json::array();
  for (long r = 0; r < runs; ++r) {
    cc::PointVector sites = start;
    long steps = 0;
    double move = std::numeric_limits<double>::infinity();
    t0 = cpu_seconds();
    while (steps < max_iterations && !(move < tolerance)) {
      const cc::Voronoi voronoi(sites, map, map_size, params.pResolution);
      const auto cells = voronoi.GetVoronoiCells();
      move = 0;
      for (std::size_t i = 0; i < n; ++i) {
        sink += cells[i].mass();
        move = std::max(move, (cells[i].centroid() - sites[i]).norm());
        sites[i] = cells[i].centroid();
      }
      ++steps;
    }
    const double t = cpu_seconds() - t0;
    out["runs"].push_back({{"cpu_s", t}, {"iterations", steps}, {"last_move", move}});
  }
  out["sink"] = sink;

  std::ofstream file(need(opt, "out"));
  file << out.dump() << '\n';
  if (!file) throw std::runtime_error("cannot write " + need(opt, "out"));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(options(argc, argv));
  } catch (const std::exception& e) {
    std::cerr << "coveragecontrol_side: " << e.what() << '\n';
    return 1;
  }
}
