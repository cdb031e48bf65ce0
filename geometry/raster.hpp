#pragma once
// A density raster: a grid of non-negative values over a rectangle, read from a CSV file
// (rows of comma-separated numbers) or a PGM image (P2 or P5). In both, the first row is
// the top of the rectangle (largest y), as in an image or a printed matrix.
#include <filesystem>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

struct Raster {
  enum class Interpolation { constant, bilinear };
  // constant: nx * ny cells tiling `extent`, each with its value. bilinear: nx * ny nodes
  // at the corners of (nx - 1) * (ny - 1) patches tiling `extent`, interpolated inside.
  Box extent;
  int nx = 0, ny = 0;
  std::vector<double> values;  // row-major, row 0 at the bottom (smallest y)
  Interpolation interpolation = Interpolation::constant;

  double at(int i, int j) const { return values[static_cast<std::size_t>(j) * nx + i]; }
  double operator()(Vec2 x) const;
};

// Rows top to bottom, as in the file. Throws std::runtime_error naming the file and line.
std::vector<std::vector<double>> read_raster_csv(const std::filesystem::path& file);
// Pixel values divided by the image's maximum value (so in [0, 1]).
std::vector<std::vector<double>> read_raster_pgm(const std::filesystem::path& file);
// Checks the rows (rectangular, finite, non-negative, at least 1x1 or 2x2 for bilinear)
// and builds the raster; throws std::invalid_argument saying what is wrong.
Raster make_raster(const std::vector<std::vector<double>>& rows_top_to_bottom, const Box& extent,
                   Raster::Interpolation interpolation);

}  // namespace covsim
