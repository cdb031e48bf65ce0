#include "analysis/figures/line_chart.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/figures/axes.hpp"

namespace covsim {

namespace {
constexpr std::uint32_t kPalette[] = {0xd62728, 0x1f5fbf, 0x2ca02c, 0xff7f0e,
                                      0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f};
}  // namespace

std::string draw_line_chart(const LineChart& chart, const FigureFile& file) {
  const double w = 680, h = 420, left = 80, right = 20, top = 40, bottom = 56;
  // The legend goes under the chart, a row per series, so it never hides a line.
  const double legend_row = 16;
  const double total_h = h + 8 + legend_row * static_cast<double>(chart.series.size());
  const auto visible = [&](double x, double y) {
    return std::isfinite(x) && std::isfinite(y) && (!chart.log_y || y > 0) &&
           (!chart.log_x || x > 0);
  };
  Box data{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
  const auto take = [&](double x, double y) {
    if (!visible(x, y)) return;
    data.lo = {std::min(data.lo.x, x), std::min(data.lo.y, y)};
    data.hi = {std::max(data.hi.x, x), std::max(data.hi.y, y)};
  };
  for (const ChartSeries& s : chart.series) {
    for (const ChartPoint& p : s.points) {
      take(p.x, p.y);
      if (s.band) take(p.x, p.lo), take(p.x, p.hi);
    }
    for (const auto& [x, y] : s.samples)
      take(x, y);
  }
  // Linear charts start at zero when their data are positive: costs and times compare.
  if (!chart.log_y && data.lo.y > 0) data.lo.y = 0;
  Canvas c(file, w, total_h);
  c.rectangle({0, 0}, {w, total_h}, Colour::hex(0xffffff));
  const Axes a = chart_axes(data, {left, top}, {w - right, h - bottom}, chart.log_y, chart.log_x);
  const Colour ink = Colour::hex(0x222222);
  draw_axes(c, a, chart.x_label, chart.y_label, true);
  c.text({left, 22}, chart.title, 13, ink);
  c.push_clip({{a.lo, {a.hi.x, a.lo.y}, a.hi, {a.lo.x, a.hi.y}}});
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const ChartSeries& s = chart.series[k];
    const std::uint32_t colour = kPalette[k % 8];
    if (s.band && !s.points.empty()) {
      std::vector<Vec2> band;
      for (const ChartPoint& p : s.points)
        if (visible(p.x, p.hi)) band.push_back(a.to_px({p.x, p.hi}));
      for (auto p = s.points.rbegin(); p != s.points.rend(); ++p)
        if (visible(p->x, p->lo)) band.push_back(a.to_px({p->x, p->lo}));
      c.fill({band}, Colour::hex(colour, 0.18));
    }
    for (const auto& [x, y] : s.samples)
      if (visible(x, y)) c.circle(a.to_px({x, y}), 2.0, Colour::hex(colour, 0.25));
    std::vector<Vec2> line;
    for (const ChartPoint& p : s.points)
      if (visible(p.x, p.y)) line.push_back(a.to_px({p.x, p.y}));
    const Stroke stroke{Colour::hex(colour), 2.0,
                        s.dashed ? std::vector{6.0, 4.0} : std::vector<double>{}};
    c.polyline(line, stroke);
    if (s.points.size() < 40)
      for (const Vec2& p : line)
        c.circle(p, 2.5, Colour::hex(colour));
  }
  if (chart.marker) {
    const double px = a.to_px({chart.marker->first, a.data.lo.y}).x;
    c.line({px, a.lo.y}, {px, a.hi.y}, Stroke{ink, 1.0, {3.0, 3.0}});
    c.text({px - 4, a.lo.y + 14}, chart.marker->second, 10, ink, Align::right);
  }
  c.pop_clip();
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const ChartSeries& s = chart.series[k];
    const double ly = h + 4 + legend_row * static_cast<double>(k);
    c.line({left, ly}, {left + 25, ly},
           Stroke{Colour::hex(kPalette[k % 8]), 2.0,
                  s.dashed ? std::vector{6.0, 4.0} : std::vector<double>{}});
    c.text({left + 32, ly + 4}, s.label, 11, ink);
  }
  return c.finish();
}

}  // namespace covsim
