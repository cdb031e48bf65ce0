#include "analysis/figures/axes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace covsim {

double tick_step(double range, int ticks) {
  const double raw = range / ticks;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

namespace {
// Where v lies between lo (0) and hi (1), on a base-10 log scale if `log`.
double fraction(double v, double lo, double hi, bool log) {
  return log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
             : (v - lo) / (hi - lo);
}

// [lo, hi] widened to whole decades; a range that is empty, not positive or not finite
// becomes one decade.
void decade_range(double& lo, double& hi) {
  if (!(lo > 0) || !std::isfinite(lo)) lo = 1e-6;
  if (!(hi > lo) || !std::isfinite(hi)) hi = 10 * lo;
  lo = std::pow(10.0, std::floor(std::log10(lo)));
  hi = std::pow(10.0, std::ceil(std::log10(hi)));
  if (!(hi > lo)) hi = 10 * lo;
}

// [lo, hi] widened to whole steps of about `count` ticks; a range that is empty or not
// finite becomes [lo, lo + 1] or [0, 1].
void tick_range(double& lo, double& hi, int count) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
  if (!(hi > lo)) hi = lo + 1;
  const double s = tick_step(hi - lo, count);
  lo = std::floor(lo / s) * s;
  hi = std::ceil(hi / s) * s;
}
}  // namespace

Vec2 Axes::to_px(Vec2 d) const {
  const double fx = fraction(d.x, data.lo.x, data.hi.x, log_x);
  const double fy = fraction(d.y, data.lo.y, data.hi.y, log_y);
  return {lo.x + fx * (hi.x - lo.x), hi.y - fy * (hi.y - lo.y)};
}

Axes chart_axes(Box data, Vec2 lo, Vec2 hi, bool log_y, bool log_x) {
  if (log_y)
    decade_range(data.lo.y, data.hi.y);
  else
    tick_range(data.lo.y, data.hi.y, 6);
  if (log_x)
    decade_range(data.lo.x, data.hi.x);
  else
    tick_range(data.lo.x, data.hi.x, 8);
  return {data, lo, hi, log_y, log_x, {}};
}

Axes category_axes(std::vector<std::string> categories, Box data, Vec2 lo, Vec2 hi) {
  Axes a = chart_axes(data, lo, hi);
  a.data.lo.x = -0.5;
  a.data.hi.x = static_cast<double>(categories.size()) - 0.5;
  a.x_categories = std::move(categories);
  return a;
}

Axes map_axes(Box data, Vec2 lo, Vec2 hi) {
  const double s = std::min((hi.x - lo.x) / data.size().x, (hi.y - lo.y) / data.size().y);
  const Vec2 half = 0.5 * Vec2{(hi.x - lo.x) / s, (hi.y - lo.y) / s};
  const Vec2 mid = 0.5 * (data.lo + data.hi);
  return {Box{mid - half, mid + half}, lo, hi, false, false, {}};
}

namespace {
std::string tick_label(double v, double step) {
  if (std::abs(v) < 1e-9 * step) v = 0.0;
  return fmt::format("{:g}", v);
}

// The ticks of one axis over [lo, hi] with their labels: every decade on a log scale, else
// about `count` steps of 1, 2 or 5 times a power of ten.
std::vector<std::pair<double, std::string>> axis_ticks(double lo, double hi, bool log, int count) {
  std::vector<std::pair<double, std::string>> out;
  if (log) {
    for (double e = std::round(std::log10(lo)); e <= std::log10(hi) + 1e-9; ++e)
      out.emplace_back(std::pow(10.0, e), fmt::format("1e{:g}", e));
  } else {
    const double s = tick_step(hi - lo, count);
    for (double v = std::ceil(lo / s - 1e-9) * s; v <= hi + 1e-9 * s; v += s)
      out.emplace_back(v, tick_label(v, s));
  }
  return out;
}
}  // namespace

namespace {
// Distances outside the frame, in text heights.
constexpr double kTick = 0.4, kTickGap = 0.25, kLabelGap = 0.45, kAscent = 0.95, kDescent = 0.25;

double widest_y_label(const Axes& a, double font) {
  double widest = 0;
  for (const auto& [y, label] : axis_ticks(a.data.lo.y, a.data.hi.y, a.log_y, 6))
    widest = std::max(widest, text_width(label, font));
  return widest;
}
}  // namespace

double axes_left_room(const Axes& a, double font) {
  return (kTick + kTickGap + kLabelGap + kAscent + kDescent + 0.2) * font + widest_y_label(a, font);
}

double axes_bottom_room(double font) {
  return (kTick + kTickGap + 2 * (kAscent + kDescent) + kLabelGap + 0.2) * font;
}

void draw_axes(Canvas& c, const Axes& a, std::string_view x_label, std::string_view y_label,
               bool grid, double font) {
  const Colour ink = Colour::hex(0x222222), light = Colour::hex(0xe4e4e4);
  const double tick = kTick * font, u = font / 10;
  const Stroke grid_line{light, 0.6 * u}, tick_line{ink, 0.8 * u};
  const double x_values = a.hi.y + tick + (kTickGap + kAscent) * font;
  std::vector<std::pair<double, std::string>> x_ticks;
  for (std::size_t k = 0; k < a.x_categories.size(); ++k)
    x_ticks.emplace_back(static_cast<double>(k), a.x_categories[k]);
  if (a.x_categories.empty()) x_ticks = axis_ticks(a.data.lo.x, a.data.hi.x, a.log_x, 8);
  for (const auto& [x, label] : x_ticks) {
    const double px = a.to_px({x, a.data.lo.y}).x;
    if (grid) c.line({px, a.lo.y}, {px, a.hi.y}, grid_line);
    c.line({px, a.hi.y}, {px, a.hi.y + tick}, tick_line);
    c.text({px, x_values}, label, font, ink, Align::centre);
  }
  for (const auto& [y, label] : axis_ticks(a.data.lo.y, a.data.hi.y, a.log_y, 6)) {
    const double py = a.to_px({a.data.lo.x, y}).y;
    if (grid) c.line({a.lo.x, py}, {a.hi.x, py}, grid_line);
    c.line({a.lo.x - tick, py}, {a.lo.x, py}, tick_line);
    // Digits' height centred on the tick.
    c.text({a.lo.x - tick - kTickGap * font, py + 0.36 * font}, label, font, ink, Align::right);
  }
  c.rectangle(a.lo, a.hi, std::nullopt, Stroke{ink, 0.8 * u});
  c.text({(a.lo.x + a.hi.x) / 2, x_values + (kDescent + kLabelGap + kAscent) * font}, x_label, font,
         ink, Align::centre);
  // Turned a quarter anticlockwise, the label's glyphs lie left of its baseline.
  const double y_label_x =
      a.lo.x - tick - (kTickGap + kLabelGap + kDescent) * font - widest_y_label(a, font);
  c.text({y_label_x, (a.lo.y + a.hi.y) / 2}, y_label, font, ink, Align::centre, 90.0);
}

}  // namespace covsim
