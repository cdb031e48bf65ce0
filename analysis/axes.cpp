#include "analysis/axes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace covsim {

double tick_step(double range, int ticks) {
  const double raw = range / ticks;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

Vec2 Axes::to_px(Vec2 d) const {
  const double fx = (d.x - data.lo.x) / (data.hi.x - data.lo.x);
  const double fy = log_y ? (std::log10(d.y) - std::log10(data.lo.y)) /
                                (std::log10(data.hi.y) - std::log10(data.lo.y))
                          : (d.y - data.lo.y) / (data.hi.y - data.lo.y);
  return {lo.x + fx * (hi.x - lo.x), hi.y - fy * (hi.y - lo.y)};
}

Axes chart_axes(Box data, Vec2 lo, Vec2 hi, bool log_y) {
  if (!std::isfinite(data.lo.x) || !std::isfinite(data.hi.x)) data.lo.x = 0, data.hi.x = 1;
  if (!(data.hi.x > data.lo.x)) data.hi.x = data.lo.x + 1;
  if (log_y) {
    if (!(data.lo.y > 0) || !std::isfinite(data.lo.y)) data.lo.y = 1e-6;
    if (!(data.hi.y > data.lo.y) || !std::isfinite(data.hi.y)) data.hi.y = 10 * data.lo.y;
    data.lo.y = std::pow(10.0, std::floor(std::log10(data.lo.y)));
    data.hi.y = std::pow(10.0, std::ceil(std::log10(data.hi.y)));
    if (!(data.hi.y > data.lo.y)) data.hi.y = 10 * data.lo.y;
  } else {
    if (!std::isfinite(data.lo.y) || !std::isfinite(data.hi.y)) data.lo.y = 0, data.hi.y = 1;
    if (!(data.hi.y > data.lo.y)) data.hi.y = data.lo.y + 1;
    const double ys = tick_step(data.hi.y - data.lo.y, 6);
    data.lo.y = std::floor(data.lo.y / ys) * ys;
    data.hi.y = std::ceil(data.hi.y / ys) * ys;
  }
  const double xs = tick_step(data.hi.x - data.lo.x, 8);
  data.lo.x = std::floor(data.lo.x / xs) * xs;
  data.hi.x = std::ceil(data.hi.x / xs) * xs;
  return {data, lo, hi, log_y};
}

Axes map_axes(Box data, Vec2 lo, Vec2 hi) {
  const double s = std::min((hi.x - lo.x) / data.size().x, (hi.y - lo.y) / data.size().y);
  const Vec2 half = 0.5 * Vec2{(hi.x - lo.x) / s, (hi.y - lo.y) / s};
  const Vec2 mid = 0.5 * (data.lo + data.hi);
  return {Box{mid - half, mid + half}, lo, hi, false};
}

namespace {
std::string tick_label(double v, double step) {
  if (std::abs(v) < 1e-9 * step) v = 0.0;
  return fmt::format("{:g}", v);
}
}  // namespace

void draw_axes(Canvas& c, const Axes& a, std::string_view x_label, std::string_view y_label,
               bool grid) {
  const Colour ink = Colour::hex(0x222222), light = Colour::hex(0xe4e4e4);
  const double font = 10, tick = 4;
  const Stroke grid_line{light, 0.6}, tick_line{ink, 0.8};
  const double xs = tick_step(a.data.hi.x - a.data.lo.x, 8);
  for (double x = std::ceil(a.data.lo.x / xs - 1e-9) * xs; x <= a.data.hi.x + 1e-9 * xs; x += xs) {
    const double px = a.to_px({x, a.data.lo.y}).x;
    if (grid) c.line({px, a.lo.y}, {px, a.hi.y}, grid_line);
    c.line({px, a.hi.y}, {px, a.hi.y + tick}, tick_line);
    c.text({px, a.hi.y + tick + font + 1}, tick_label(x, xs), font, ink, Align::centre);
  }
  std::vector<std::pair<double, std::string>> yticks;
  if (a.log_y) {
    for (double e = std::round(std::log10(a.data.lo.y)); e <= std::log10(a.data.hi.y) + 1e-9; ++e)
      yticks.emplace_back(std::pow(10.0, e), fmt::format("1e{:g}", e));
  } else {
    const double ys = tick_step(a.data.hi.y - a.data.lo.y, 6);
    for (double y = std::ceil(a.data.lo.y / ys - 1e-9) * ys; y <= a.data.hi.y + 1e-9 * ys; y += ys)
      yticks.emplace_back(y, tick_label(y, ys));
  }
  double widest = 0;
  for (const auto& [y, label] : yticks) {
    const double py = a.to_px({a.data.lo.x, y}).y;
    if (grid) c.line({a.lo.x, py}, {a.hi.x, py}, grid_line);
    c.line({a.lo.x - tick, py}, {a.lo.x, py}, tick_line);
    c.text({a.lo.x - tick - 2, py + font / 2 - 1}, label, font, ink, Align::right);
    widest = std::max(widest, c.text_width(label, font));
  }
  c.rectangle(a.lo, a.hi, std::nullopt, Stroke{ink, 0.8});
  c.text({(a.lo.x + a.hi.x) / 2, a.hi.y + tick + 2 * font + 8}, x_label, font + 1, ink,
         Align::centre);
  c.text({a.lo.x - tick - widest - 8, (a.lo.y + a.hi.y) / 2}, y_label, font + 1, ink, Align::centre,
         90.0);
}

}  // namespace covsim
