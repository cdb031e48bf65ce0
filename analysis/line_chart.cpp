#include "analysis/line_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/xml_escape.hpp"

namespace covsim {

namespace {
// A tick step of 1, 2 or 5 times a power of ten, giving about `ticks` ticks.
double tick_step(double range, int ticks) {
  const double raw = range / ticks;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * p >= raw) return m * p;
  }
  return 10 * p;
}

constexpr const char* kPalette[] = {"#d62728", "#1f5fbf", "#2ca02c", "#ff7f0e",
                                    "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};
}  // namespace

std::string line_chart_svg(const std::string& title, const std::string& x_label,
                           const std::string& y_label, const std::vector<ChartSeries>& series) {
  const double w = 680, h = 420, left = 80, right = 20, top = 40, bottom = 50;
  // The legend goes under the chart, a row per series, so it never hides a line.
  const double legend_row = 16, total_h = h + 8 + legend_row * static_cast<double>(series.size());
  double x0 = INFINITY, x1 = -INFINITY, y0 = 0.0, y1 = -INFINITY;
  for (const ChartSeries& s : series) {
    for (const ChartPoint& p : s.points) {
      x0 = std::min(x0, p.x);
      x1 = std::max(x1, p.x);
      y0 = std::min({y0, p.y, s.band ? p.lo : p.y});
      y1 = std::max({y1, p.y, s.band ? p.hi : p.y});
    }
    for (const auto& [x, y] : s.samples) {
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1;
  if (!(x1 > x0)) x1 = x0 + 1;
  if (!std::isfinite(y1) || !(y1 > y0)) y1 = y0 + 1;
  const double xs = tick_step(x1 - x0, 8), ys = tick_step(y1 - y0, 6);
  x0 = std::floor(x0 / xs) * xs;
  x1 = std::ceil(x1 / xs) * xs;
  y0 = std::floor(y0 / ys) * ys;
  y1 = std::ceil(y1 / ys) * ys;
  const auto X = [&](double x) { return left + (w - left - right) * (x - x0) / (x1 - x0); };
  const auto Y = [&](double y) { return h - bottom - (h - top - bottom) * (y - y0) / (y1 - y0); };
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"{0}\" height=\"{1}\" "
      "fill=\"#ffffff\"/>\n",
      w, total_h);
  out += fmt::format("<text x=\"{:.1f}\" y=\"20\" font-size=\"14\">{}</text>\n", left,
                     xml_escape(title));
  for (double x = x0; x <= x1 + 1e-9 * xs; x += xs) {
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#e0e0e0\"/>\n",
        X(x), Y(y0), Y(y1));
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:g}</text>\n", X(x),
                       Y(y0) + 16, x);
  }
  for (double y = y0; y <= y1 + 1e-9 * ys; y += ys) {
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#e0e0e0\"/>\n",
        X(x0), Y(y), X(x1));
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:g}</text>\n",
                       X(x0) - 6, Y(y) + 4, y);
  }
  out += fmt::format(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
      "stroke=\"#000\"/>\n",
      X(x0), Y(y1), X(x1) - X(x0), Y(y0) - Y(y1));
  for (std::size_t k = 0; k < series.size(); ++k) {
    const ChartSeries& s = series[k];
    const char* colour = kPalette[k % 8];
    if (s.band && !s.points.empty()) {
      std::string band;
      for (const ChartPoint& p : s.points)
        band += fmt::format("{:.2f},{:.2f} ", X(p.x), Y(p.hi));
      for (auto p = s.points.rbegin(); p != s.points.rend(); ++p)
        band += fmt::format("{:.2f},{:.2f} ", X(p->x), Y(p->lo));
      out += fmt::format(
          "<polygon points=\"{}\" fill=\"{}\" fill-opacity=\"0.18\" stroke=\"none\"/>\n", band,
          colour);
    }
    for (const auto& [x, y] : s.samples) {
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      out += fmt::format(
          "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2\" fill=\"{}\" fill-opacity=\"0.25\"/>\n", X(x),
          Y(y), colour);
    }
    std::string pts;
    for (const ChartPoint& p : s.points)
      pts += fmt::format("{:.2f},{:.2f} ", X(p.x), Y(p.y));
    out +=
        fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{} points=\"{}\"/>\n",
                    colour, s.dashed ? " stroke-dasharray=\"6,4\"" : "", pts);
    if (s.points.size() < 40) {
      for (const ChartPoint& p : s.points) {
        out += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2.5\" fill=\"{}\"/>\n", X(p.x),
                           Y(p.y), colour);
      }
    }
    const double ly = h + 4 + legend_row * static_cast<double>(k);
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
        "stroke-width=\"2\"{4}/>"
        "<text x=\"{5:.1f}\" y=\"{6:.1f}\">{7}</text>\n",
        left, ly, left + 25, colour, s.dashed ? " stroke-dasharray=\"6,4\"" : "", left + 32, ly + 4,
        xml_escape(s.label));
  }
  out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n",
                     (X(x0) + X(x1)) / 2, h - 12, xml_escape(x_label));
  out += fmt::format(
      "<text x=\"18\" y=\"{0:.1f}\" text-anchor=\"middle\" transform=\"rotate(-90 18 "
      "{0:.1f})\">{1}</text>\n",
      (Y(y0) + Y(y1)) / 2, xml_escape(y_label));
  return out + "</svg>\n";
}

}  // namespace covsim
