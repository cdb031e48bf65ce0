#pragma once
// A line chart: series of (x, y) with an optional band [lo, hi] around each line and the
// individual runs as faint dots, drawn through the Canvas in any figure format; or, over
// categories, a strip chart of the same series.
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/figures/canvas.hpp"

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

struct LineChart {
  std::string title, x_label, y_label;
  std::vector<ChartSeries> series;
  bool log_y = false;
  bool log_x = false;  // points with x <= 0 are not drawn on a log x axis
  // Categories along x (a planner, a loop schedule): category k at x = k. Each series is then
  // drawn beside the others at each category, its runs as dots and its mean as a point with
  // its band as a whisker, without lines between categories.
  std::vector<std::string> x_categories;
  // Values of y the axis covers besides the data's (NaN: none): panels of one figure share
  // their y range.
  double y_cover_lo = NAN, y_cover_hi = NAN;
  // A vertical line marking an x (the convergence time, say), with its label.
  std::optional<std::pair<double, std::string>> marker;
};

// The chart file.size wide and high (or about 0.62 of its width), its legend under it.
std::string draw_line_chart(const LineChart& chart, const FigureFile& file);
// Charts stacked one above the other in one figure, each as tall as draw_line_chart's (or
// the file's height shared among them): small multiples, one panel per facet.
std::string draw_chart_panels(const std::vector<LineChart>& panels, const FigureFile& file);

}  // namespace covsim
