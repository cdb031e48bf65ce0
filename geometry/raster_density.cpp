#include "geometry/raster_density.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/environment.hpp"
#include "geometry/quadrature.hpp"

namespace covsim {

namespace {
constexpr int kBilinearPoints = 3;  // exact to degree 4: bilinear times |x - r|^2
}  // namespace

Moments RasterDensity::integrate(const ConvexPolygon& piece, Vec2 r) const {
  if (piece.size() < 3) return {};
  const Raster& m = raster_;
  // Clip the piece to each raster cell (or bilinear patch) it overlaps; the density is a
  // polynomial on each.
  Box box;
  for (Vec2 p : piece)
    box.add(p);
  const int cx = m.interpolation == Raster::Interpolation::constant ? m.nx : m.nx - 1;
  const int cy = m.interpolation == Raster::Interpolation::constant ? m.ny : m.ny - 1;
  const Vec2 cell{m.extent.size().x / cx, m.extent.size().y / cy};
  // Outside the extent the border cells extend outwards (the loader requires the extent
  // to cover Ω, so this only matters for rounding at the edge).
  const auto index = [](double v, int n) {
    return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1);
  };
  const int i0 = index((box.lo.x - m.extent.lo.x) / cell.x, cx),
            i1 = index((box.hi.x - m.extent.lo.x) / cell.x, cx);
  const int j0 = index((box.lo.y - m.extent.lo.y) / cell.y, cy),
            j1 = index((box.hi.y - m.extent.lo.y) / cell.y, cy);
  Moments out;
  ConvexPolygon a, b;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const double x0 = m.extent.lo.x + i * cell.x, y0 = m.extent.lo.y + j * cell.y;
      a = piece;
      if (i > 0) clip(a, HalfPlane{{-1, 0}, -x0}, b), a.swap(b);
      if (i < cx - 1) clip(a, HalfPlane{{1, 0}, x0 + cell.x}, b), a.swap(b);
      if (j > 0) clip(a, HalfPlane{{0, -1}, -y0}, b), a.swap(b);
      if (j < cy - 1) clip(a, HalfPlane{{0, 1}, y0 + cell.y}, b), a.swap(b);
      if (a.size() < 3) continue;
      if (m.interpolation == Raster::Interpolation::constant) {
        out += polygon_moments(a, r).scaled(m.at(i, j));
        continue;
      }
      const double v00 = m.at(i, j), v10 = m.at(i + 1, j), v01 = m.at(i, j + 1),
                   v11 = m.at(i + 1, j + 1);
      const auto f = [&](Vec2 x) {
        const double fx = (x.x - x0) / cell.x, fy = (x.y - y0) / cell.y;
        return (1 - fx) * (1 - fy) * v00 + fx * (1 - fy) * v10 + (1 - fx) * fy * v01 +
               fx * fy * v11;
      };
      for (std::size_t k = 1; k + 1 < a.size(); ++k)
        out += triangle_moments(a[0], a[k], a[k + 1], r, f, kBilinearPoints);
    }
  }
  return out;
}

DensityEntry raster_density_entry() {
  DensityEntry e;
  e.name = "raster";
  e.description = "values on a grid read from a CSV or PGM file (first row at the top)";
  e.params = {ParamSpec::text("file", "a .csv or .pgm file, relative to the scenario file"),
              ParamSpec::extent("extent", "m", "the rectangle the grid covers (must cover Ω)"),
              ParamSpec::choice("interpolation", {"constant", "bilinear"},
                                "constant per cell, or bilinear between nodes")
                  .defaults_to(std::string("constant")),
              ParamSpec::number("scale", "", "every value is multiplied by it")
                  .greater_than(0)
                  .defaults_to(1.0)};
  e.make = [](const DensityContext& ctx, const Params& p) {
    const Box box = p.extent("extent");
    if (!box.contains(ctx.environment.bounds()))
      throw ParamError("extent", "the raster must cover the environment's bounding box");
    const auto interp = p.text("interpolation") == "bilinear" ? Raster::Interpolation::bilinear
                                                              : Raster::Interpolation::constant;
    const std::filesystem::path path = ctx.base_dir / p.text("file");
    const std::string ext = path.extension().string();
    if (ext != ".csv" && ext != ".pgm") throw ParamError("file", "expected a .csv or .pgm file");
    try {
      std::vector<std::vector<double>> rows =
          ext == ".csv" ? read_raster_csv(path) : read_raster_pgm(path);
      for (auto& row : rows) {
        for (double& x : row)
          x *= p.number("scale");
      }
      return std::make_shared<const RasterDensity>(make_raster(rows, box, interp));
    } catch (const std::exception& e) {
      throw ParamError("file", e.what());
    }
  };
  return e;
}

}  // namespace covsim
