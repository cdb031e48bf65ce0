#pragma once
// A line chart as SVG: series of (x, y) with an optional band [lo, hi] around each line.
#include <string>
#include <utility>
#include <vector>

namespace covsim {

struct ChartPoint {
  double x, y;
  double lo = 0.0, hi = 0.0;  // the band; ignored unless the series has one
};
struct ChartSeries {
  std::string label;
  std::vector<ChartPoint> points;
  bool band = false;
  bool dashed = false;
  // Individual observations (one per run), drawn as faint dots under the line.
  std::vector<std::pair<double, double>> samples;
};

std::string line_chart_svg(const std::string& title, const std::string& x_label,
                           const std::string& y_label, const std::vector<ChartSeries>& series);

}  // namespace covsim
