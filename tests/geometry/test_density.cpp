#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "geometry/gaussian_mixture_density.hpp"
#include "geometry/quadrature.hpp"
#include "geometry/raster_density.hpp"
#include "geometry/uniform_density.hpp"
#include "geometry/voronoi_partition.hpp"
#include "tests/geometry/shapes.hpp"

using namespace covsim;
using covsim::test::square;
namespace fs = std::filesystem;

namespace {

// ∫_a^b exp(-(x-mu)²/(2 s²)) dx and ∫_a^b x exp(...) dx, in closed form.
double g0(double a, double b, double mu, double s) {
  return s * std::sqrt(M_PI / 2) *
         (std::erf((b - mu) / (s * M_SQRT2)) - std::erf((a - mu) / (s * M_SQRT2)));
}
double g1(double a, double b, double mu, double s) {
  return mu * g0(a, b, mu, s) + s * s *
                                    (std::exp(-(a - mu) * (a - mu) / (2 * s * s)) -
                                     std::exp(-(b - mu) * (b - mu) / (2 * s * s)));
}

fs::path temp_file(const std::string& name, const std::string& text, bool binary = false) {
  const fs::path p =
      fs::temp_directory_path() / ("covsim-density-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream(p, binary ? std::ios::binary : std::ios::out) << text;
  return p;
}
}  // namespace

TEST_CASE("Gauss-Legendre rules integrate polynomials exactly", "[quadrature]") {
  for (int m : {1, 2, 3, 8, 16}) {
    const auto& q = gauss_legendre(m);
    double sum = 0;
    for (double w : q.weights)
      sum += w;
    CHECK(sum == Approx(1.0).epsilon(1e-14));
    // ∫_0^1 x^(2m-1) = 1/(2m).
    double moment = 0;
    for (int i = 0; i < m; ++i)
      moment += q.weights[i] * std::pow(q.nodes[i], 2 * m - 1);
    CHECK(moment == Approx(1.0 / (2 * m)).epsilon(1e-13));
  }
  // Degree 4 on a triangle with 3 points: ∫ x²y² over the unit right triangle = 1/180.
  const Moments m = triangle_moments(
      {0, 0}, {1, 0}, {0, 1}, {0, 0}, [](Vec2 x) { return x.x * x.x * x.y * x.y; }, 3);
  CHECK(m.mass == Approx(1.0 / 180.0).epsilon(1e-13));
}

TEST_CASE("Gaussian mixture mass and centroid to 1e-13 at sigma = diameter / 20", "[density]") {
  // Ω = [-1, 1]²: the diameter of its box is 2√2, so sigma = 0.1414 is 1/20 of it.
  const double sigma = 2 * M_SQRT2 / 20;
  const Vec2 mu{0.3, -0.2};
  const double floor = 0.05;
  const Environment env(square(-1, -1, 1, 1), {});
  const GaussianMixtureDensity d({{mu, sigma, 2.0}}, floor);
  const CellIntegrator cells(env, d);
  // Closed form on the square, separable in x and y.
  const double mass = 2.0 * g0(-1, 1, mu.x, sigma) * g0(-1, 1, mu.y, sigma) + floor * 4.0;
  const double sx = 2.0 * g1(-1, 1, mu.x, sigma) * g0(-1, 1, mu.y, sigma);
  const double sy = 2.0 * g0(-1, 1, mu.x, sigma) * g1(-1, 1, mu.y, sigma);
  CHECK(cells.total_mass() == Approx(mass).epsilon(1e-13));

  // Over a partition into cells: the sums match the closed form, and each cell matches a
  // quadrature reference on triangles sixteen times smaller with 20x20 points.
  VoronoiPartition part(cells, {{-0.5, -0.5}, {0.4, -0.3}, {0.1, 0.6}, {0.9, 0.9}, {0.25, -0.15}});
  double total = 0;
  Vec2 first{0, 0};
  for (std::size_t i = 0; i < part.size(); ++i) {
    const Moments m = part.moments(i);
    total += m.mass;
    first += m.first + m.mass * part.generators()[i];
    Moments ref;
    const auto f = [&](Vec2 x) { return d(x); };
    cells.for_each_piece(
        {part.cell(i).begin(), part.cell(i).end()}, [&](const ConvexPolygon& piece) {
          for (std::size_t k = 1; k + 1 < piece.size(); ++k) {
            // Split each fan triangle into 16 by midpoints, twice.
            std::vector<std::array<Vec2, 3>> tris{{piece[0], piece[k], piece[k + 1]}};
            for (int level = 0; level < 4; ++level) {
              std::vector<std::array<Vec2, 3>> next;
              for (auto& t : tris) {
                const Vec2 ab = 0.5 * (t[0] + t[1]), bc = 0.5 * (t[1] + t[2]),
                           ca = 0.5 * (t[2] + t[0]);
                next.push_back({t[0], ab, ca});
                next.push_back({ab, t[1], bc});
                next.push_back({ca, bc, t[2]});
                next.push_back({ab, bc, ca});
              }
              tris.swap(next);
            }
            for (auto& t : tris)
              ref += triangle_moments(t[0], t[1], t[2], part.generators()[i], f, 20);
          }
        });
    CHECK(m.mass == Approx(ref.mass).epsilon(1e-13));
    const Vec2 c = part.generators()[i] + m.first / m.mass;
    const Vec2 cref = part.generators()[i] + ref.first / ref.mass;
    CHECK(distance(c, cref) <= 1e-13 * (norm(cref) + 1.0));
    CHECK(m.second == Approx(ref.second).epsilon(1e-13));
  }
  CHECK(total == Approx(mass).epsilon(1e-13));
  CHECK(first.x / total == Approx(sx / mass).epsilon(1e-13));
  CHECK(first.y / total == Approx(sy / mass).epsilon(1e-13));
}

TEST_CASE("a Gaussian much narrower than Ω integrates where it is, to the closed form",
          "[density]") {
  // σ = 0.1 m in a 1000 m room (it once took minutes: triangles of side σ everywhere).
  const double sigma = 0.1, floor = 1e-3;
  const Vec2 mu{500.3, 499.8};
  const Environment env(square(0, 0, 1000, 1000), {});
  const GaussianMixtureDensity d({{mu, sigma, 3.0}}, floor);
  const CellIntegrator cells(env, d);
  const double mass = 3.0 * 2.0 * M_PI * sigma * sigma + floor * 1e6;
  CHECK(cells.total_mass() == Approx(mass).epsilon(1e-13));
  // A cell holding the bump and one without it: the bump's mass where it lies.
  VoronoiPartition part(cells, {{500, 500}, {100, 100}});
  const double near = part.moments(0).mass, far = part.moments(1).mass;
  // The bisector x + y = 600 leaves the far cell a triangle of 180 000 m².
  CHECK(far == Approx(floor * 180000.0).epsilon(1e-13));
  CHECK(near == Approx(3.0 * 2.0 * M_PI * sigma * sigma + floor * 820000.0).epsilon(1e-13));
}

TEST_CASE("constant and bilinear rasters integrate exactly", "[density]") {
  const Environment env(square(0, 0, 2, 2), {});
  // Rows top to bottom: the top row is y in [1, 2].
  const Raster r =
      make_raster({{3, 4}, {1, 2}}, Box{{0, 0}, {2, 2}}, Raster::Interpolation::constant);
  CHECK(r({0.5, 0.5}) == 1);
  CHECK(r({1.5, 1.5}) == 4);
  const RasterDensity d(r);
  const CellIntegrator cells(env, d);
  VoronoiPartition part(cells, {{0.3, 1.0}, {1.7, 1.0}});  // split at x = 1
  CHECK(part.summary(0).mass == Approx(1 + 3));
  CHECK(part.summary(1).mass == Approx(2 + 4));
  CHECK(part.summary(0).centroid.y == Approx((1 * 0.5 + 3 * 1.5) / 4));

  // Bilinear between nodes reproduces 1 + x + 2y on [0, 2]² exactly.
  const Raster b =
      make_raster({{5, 7}, {1, 3}}, Box{{0, 0}, {2, 2}}, Raster::Interpolation::bilinear);
  CHECK(b({1, 1}) == Approx(4));
  const RasterDensity db(b);
  const CellIntegrator cb(env, db);
  // ∫ (1 + x + 2y) over [0,2]² = 4 + 4 + 8 = 16; ∫ x(1 + x + 2y) = 4 + 16/3 + 8 = 52/3.
  VoronoiPartition whole(cb, {{1, 1}});
  CHECK(whole.summary(0).mass == Approx(16.0).epsilon(1e-13));
  CHECK(whole.summary(0).centroid.x == Approx(52.0 / 3.0 / 16.0).epsilon(1e-13));
}

TEST_CASE("rasters load from CSV and PGM, and bad files are reported", "[density]") {
  const auto csv = read_raster_csv(temp_file("ok.csv", "1, 2, 3\n4,5,6\n"));
  REQUIRE(csv.size() == 2);
  CHECK(csv[1][2] == 6);
  const auto pgm =
      read_raster_pgm(temp_file("ok.pgm", "P2\n# a comment\n3 2\n10\n0 5 10\n10 5 0\n"));
  REQUIRE(pgm.size() == 2);
  CHECK(pgm[0][1] == 0.5);
  const std::string binary = std::string("P5\n2 1\n255\n") + char(0) + char(255);
  const auto p5 = read_raster_pgm(temp_file("ok5.pgm", binary, true));
  CHECK(p5[0][1] == 1.0);

  CHECK_THROWS_WITH(read_raster_csv(temp_file("bad.csv", "1,2\n3,x\n")),
                    Catch::Contains("bad.csv:2: 'x' is not a number"));
  CHECK_THROWS_WITH(read_raster_pgm(temp_file("bad.pgm", "P3\n1 1\n1\n0\n")),
                    Catch::Contains("not a PGM"));
  CHECK_THROWS_WITH(read_raster_pgm(temp_file("short.pgm", "P2\n2 2\n10\n1 2 3\n")),
                    Catch::Contains("ends early"));
  CHECK_THROWS_WITH(
      make_raster({{1, 2}, {3}}, Box{{0, 0}, {1, 1}}, Raster::Interpolation::constant),
      Catch::Contains("row 1 has 1 values"));
  CHECK_THROWS_WITH(make_raster({{1, -2}}, Box{{0, 0}, {1, 1}}, Raster::Interpolation::constant),
                    Catch::Contains("non-negative"));
  CHECK_THROWS_WITH(make_raster({{1}}, Box{{0, 0}, {1, 1}}, Raster::Interpolation::bilinear),
                    Catch::Contains("2x2"));
}

TEST_CASE("densities reject invalid parameters", "[density]") {
  CHECK_THROWS(UniformDensity(0.0));
  CHECK_THROWS(GaussianMixtureDensity({{{0, 0}, 0.0, 1.0}}, 0.0));
  CHECK_THROWS(GaussianMixtureDensity({{{0, 0}, 1.0, -1.0}}, 0.0));
  CHECK_THROWS(GaussianMixtureDensity({{{NAN, 0}, 1.0, 1.0}}, 0.0));
  CHECK_THROWS(GaussianMixtureDensity({}, -1.0));
}
