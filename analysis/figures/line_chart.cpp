#include "analysis/figures/line_chart.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/figures/axes.hpp"
#include "analysis/figures/legend.hpp"

namespace covsim {

namespace {
constexpr std::uint32_t kPalette[] = {0xd62728, 0x1f5fbf, 0x2ca02c, 0xff7f0e,
                                      0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f};
}  // namespace

namespace {
// One chart into the band of the canvas from y0 down h, the full width w.
void draw_chart(Canvas& c, const LineChart& chart, const FigureFile& file, double y0, double h) {
  const double f = file.size.font, u = file.size.unit(), pad = 0.6 * f, w = file.size.width;
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
  for (const double y : {chart.y_cover_lo, chart.y_cover_hi})
    if (std::isfinite(y) && (!chart.log_y || y > 0)) {
      data.lo.y = std::min(data.lo.y, y);
      data.hi.y = std::max(data.hi.y, y);
    }
  // Linear charts start at zero when their data are positive: costs and times compare.
  if (!chart.log_y && data.lo.y > 0) data.lo.y = 0;
  const auto line = [&](std::size_t k) {
    const bool dashed = chart.series[k].dashed;
    return Stroke{Colour::hex(kPalette[k % 8]), 1.5 * u,
                  dashed ? std::vector{4.5 * u, 3.0 * u} : std::vector<double>{}};
  };
  // Laid out before drawing: the title's lines, the axes' labels, and the legend under the
  // chart, so that it never hides a line.
  std::vector<LegendEntry> entries;
  for (std::size_t k = 0; k < chart.series.size(); ++k)
    entries.push_back({chart.series[k].label, [s = line(k), f](Canvas& c, Vec2 p) {
                         c.line(p - Vec2{0.9 * f, 0}, p + Vec2{0.9 * f, 0}, s);
                       }});
  const Legend legend(std::move(entries), f);
  const int columns = legend.columns_within(w - 2 * pad);
  const double legend_h = legend.empty() ? 0 : legend.size(columns).y + pad;
  const double title_font = f + 1;
  const auto title = wrap_text(chart.title, title_font, w - 2 * pad);
  const double top = y0 + pad + 1.3 * title_font * static_cast<double>(title.size()) + pad;
  const bool categorical = !chart.x_categories.empty();
  Axes a = categorical ? category_axes(chart.x_categories, data, {0, 0}, {1, 1})
                       : chart_axes(data, {0, 0}, {1, 1}, chart.log_y, chart.log_x);
  a.lo = {axes_left_room(a, f), top};
  a.hi = {w - 1.5 * pad, y0 + h - legend_h - axes_bottom_room(f)};

  const Colour ink = Colour::hex(0x222222);
  draw_axes(c, a, chart.x_label, chart.y_label, true, f);
  for (std::size_t k = 0; k < title.size(); ++k)
    c.text({pad, y0 + pad + title_font * (1.3 * k + 1.0)}, title[k], title_font, ink);
  c.push_clip({{a.lo, {a.hi.x, a.lo.y}, a.hi, {a.lo.x, a.hi.y}}});
  for (std::size_t k = 0; k < chart.series.size() && categorical; ++k) {
    // Series side by side within a category's width.
    const ChartSeries& s = chart.series[k];
    const std::uint32_t colour = kPalette[k % 8];
    const double n = static_cast<double>(chart.series.size());
    const double dx = 0.7 / n * (static_cast<double>(k) - (n - 1) / 2);
    for (const auto& [x, y] : s.samples)
      if (visible(x, y)) c.circle(a.to_px({x + dx, y}), 1.6 * u, Colour::hex(colour, 0.35));
    for (const ChartPoint& p : s.points) {
      if (!visible(p.x, p.y)) continue;
      if (s.band && visible(p.x, p.lo) && visible(p.x, p.hi))
        c.line(a.to_px({p.x + dx, p.lo}), a.to_px({p.x + dx, p.hi}), line(k));
      c.circle(a.to_px({p.x + dx, p.y}), 2.6 * u, Colour::hex(colour));
    }
  }
  for (std::size_t k = 0; k < chart.series.size() && !categorical; ++k) {
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
      if (visible(x, y)) c.circle(a.to_px({x, y}), 1.6 * u, Colour::hex(colour, 0.25));
    std::vector<Vec2> points;
    for (const ChartPoint& p : s.points)
      if (visible(p.x, p.y)) points.push_back(a.to_px({p.x, p.y}));
    c.polyline(points, line(k));
    if (s.points.size() < 40)
      for (const Vec2& p : points)
        c.circle(p, 2.0 * u, Colour::hex(colour));
  }
  if (chart.marker) {
    const double px = a.to_px({chart.marker->first, a.data.lo.y}).x;
    c.line({px, a.lo.y}, {px, a.hi.y}, Stroke{ink, 0.8 * u, {3.0 * u, 3.0 * u}});
    c.text({px - 0.4 * f, a.lo.y + 1.3 * f}, chart.marker->second, f, ink, Align::right);
  }
  c.pop_clip();
  if (!legend.empty()) legend.draw(c, {pad, y0 + h - legend_h}, columns);
}
}  // namespace

std::string draw_line_chart(const LineChart& chart, const FigureFile& file) {
  const double w = file.size.width, h = file.size.height > 0 ? file.size.height : 0.62 * w;
  Canvas c(file, w, h);
  c.rectangle({0, 0}, {w, h}, Colour::hex(0xffffff));
  draw_chart(c, chart, file, 0.0, h);
  return c.finish();
}

std::string draw_chart_panels(const std::vector<LineChart>& panels, const FigureFile& file) {
  const double w = file.size.width;
  const double h =
      file.size.height > 0 ? file.size.height : 0.62 * w * static_cast<double>(panels.size());
  const double each = h / static_cast<double>(std::max<std::size_t>(1, panels.size()));
  Canvas c(file, w, h);
  c.rectangle({0, 0}, {w, h}, Colour::hex(0xffffff));
  for (std::size_t k = 0; k < panels.size(); ++k)
    draw_chart(c, panels[k], file, each * static_cast<double>(k), each);
  return c.finish();
}

}  // namespace covsim
