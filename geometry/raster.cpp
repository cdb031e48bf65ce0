#include "geometry/raster.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "io/bounded_read.hpp"

namespace covsim {

double Raster::operator()(Vec2 x) const {
  const Vec2 size = extent.size();
  if (interpolation == Interpolation::constant) {
    const int i =
        std::clamp(static_cast<int>(std::floor((x.x - extent.lo.x) / size.x * nx)), 0, nx - 1);
    const int j =
        std::clamp(static_cast<int>(std::floor((x.y - extent.lo.y) / size.y * ny)), 0, ny - 1);
    return at(i, j);
  }
  const double gx = std::clamp((x.x - extent.lo.x) / size.x * (nx - 1), 0.0, nx - 1.0);
  const double gy = std::clamp((x.y - extent.lo.y) / size.y * (ny - 1), 0.0, ny - 1.0);
  const int i = std::min(static_cast<int>(gx), nx - 2), j = std::min(static_cast<int>(gy), ny - 2);
  const double fx = gx - i, fy = gy - j;
  return (1 - fx) * (1 - fy) * at(i, j) + fx * (1 - fy) * at(i + 1, j) +
         (1 - fx) * fy * at(i, j + 1) + fx * fy * at(i + 1, j + 1);
}

std::vector<std::vector<double>> read_raster_csv(const std::filesystem::path& file) {
  std::istringstream in(read_whole_file(file));
  std::vector<std::vector<double>> rows;
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      std::size_t used = 0;
      double v;
      try {
        v = std::stod(cell, &used);
      } catch (const std::exception&) {
        throw std::runtime_error(
            fmt::format("{}:{}: '{}' is not a number", file.string(), lineno, cell));
      }
      if (cell.find_first_not_of(" \t\r", used) != std::string::npos) {
        throw std::runtime_error(
            fmt::format("{}:{}: '{}' is not a number", file.string(), lineno, cell));
      }
      row.push_back(v);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<std::vector<double>> read_raster_pgm(const std::filesystem::path& file) {
  std::istringstream in(read_whole_file(file));
  auto fail = [&](const std::string& what) -> std::runtime_error {
    return std::runtime_error(file.string() + ": " + what);
  };
  // Header tokens, skipping '#' comments.
  auto token = [&]() {
    std::string t;
    char c;
    while (in.get(c)) {
      if (c == '#') {
        std::string rest;
        std::getline(in, rest);
        if (!t.empty()) break;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        if (!t.empty()) break;
      } else {
        t += c;
      }
    }
    return t;
  };
  const std::string magic = token();
  if (magic != "P2" && magic != "P5") throw fail("not a PGM image (expected P2 or P5)");
  long w = 0, h = 0, maxval = 0;
  try {
    w = std::stol(token());
    h = std::stol(token());
    maxval = std::stol(token());
  } catch (const std::exception&) {
    throw fail("malformed PGM header");
  }
  if (w <= 0 || h <= 0 || w * h > 100'000'000 || maxval <= 0 || maxval > 65535)
    throw fail("malformed PGM header");
  std::vector<std::vector<double>> rows(static_cast<std::size_t>(h),
                                        std::vector<double>(static_cast<std::size_t>(w)));
  for (long j = 0; j < h; ++j) {
    for (long i = 0; i < w; ++i) {
      long v = 0;
      if (magic == "P2") {
        const std::string t = token();
        if (t.empty()) throw fail("PGM image ends early");
        try {
          v = std::stol(t);
        } catch (const std::exception&) {
          throw fail("'" + t + "' is not a pixel value");
        }
      } else {
        unsigned char b[2];
        const int bytes = maxval > 255 ? 2 : 1;
        if (!in.read(reinterpret_cast<char*>(b), bytes)) throw fail("PGM image ends early");
        v = bytes == 2 ? (b[0] << 8) | b[1] : b[0];
      }
      if (v < 0 || v > maxval)
        throw fail(fmt::format("pixel ({}, {}) = {} exceeds the maximum {}", i, j, v, maxval));
      rows[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] =
          static_cast<double>(v) / static_cast<double>(maxval);
    }
  }
  return rows;
}

Raster make_raster(const std::vector<std::vector<double>>& rows, const Box& extent,
                   Raster::Interpolation interp) {
  const int min_side = interp == Raster::Interpolation::bilinear ? 2 : 1;
  if (rows.empty() || static_cast<int>(rows.size()) < min_side ||
      static_cast<int>(rows[0].size()) < min_side) {
    throw std::invalid_argument(fmt::format("a raster needs at least {0}x{0} values", min_side));
  }
  if (!(extent.hi.x > extent.lo.x && extent.hi.y > extent.lo.y) || !is_finite(extent.lo) ||
      !is_finite(extent.hi)) {
    throw std::invalid_argument("a raster's extent must be a finite rectangle of positive size");
  }
  Raster r;
  r.extent = extent;
  r.interpolation = interp;
  r.nx = static_cast<int>(rows[0].size());
  r.ny = static_cast<int>(rows.size());
  r.values.resize(static_cast<std::size_t>(r.nx) * r.ny);
  for (int j = 0; j < r.ny; ++j) {
    const auto& row = rows[static_cast<std::size_t>(r.ny - 1 - j)];
    if (static_cast<int>(row.size()) != r.nx) {
      throw std::invalid_argument(fmt::format("raster row {} has {} values, the first row has {}",
                                              r.ny - 1 - j, row.size(), r.nx));
    }
    for (int i = 0; i < r.nx; ++i) {
      const double v = row[static_cast<std::size_t>(i)];
      if (!std::isfinite(v) || v < 0.0) {
        throw std::invalid_argument(
            fmt::format("raster value at row {}, column {} is {}: values must be finite and "
                        "non-negative",
                        r.ny - 1 - j, i, v));
      }
      r.values[static_cast<std::size_t>(j) * r.nx + i] = v;
    }
  }
  return r;
}

}  // namespace covsim
