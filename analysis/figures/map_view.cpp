#include "analysis/figures/map_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "analysis/figures/marks.hpp"

namespace covsim {

Colour density_colour(double t) {
  // ColorBrewer's YlOrBr, from white.
  static constexpr std::array<std::uint32_t, 7> stops = {0xffffff, 0xfff7bc, 0xfee391, 0xfec44f,
                                                         0xfe9929, 0xec7014, 0xcc4c02};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (stops.size() - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(t), stops.size() - 2);
  const double f = t - static_cast<double>(k);
  const Colour a = Colour::hex(stops[k]), b = Colour::hex(stops[k + 1]);
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), 1.0};
}

Box MapView::extent(const Scenario& scenario) {
  const Box& b = scenario.environment->bounds();
  const Vec2 pad = 0.03 * b.size();
  return Box{b.lo - pad, b.hi + pad};
}

double MapView::aspect(const Scenario& scenario) {
  const Box e = extent(scenario);
  return std::clamp(e.size().y / e.size().x, 0.3, 1.6);
}

MapView::MapView(const Scenario& scenario) : scenario_(scenario) {
  const Box& b = scenario.environment->bounds();
  place({0, 0}, {1, aspect(scenario)});
  // The density sampled at pixel centres over Ω's box, about 2 pixels per point on the
  // longer side (an image: a few kB, whatever the density).
  uniform_ = scenario.density->is_uniform();
  if (uniform_) return;
  const double longest = std::max(b.size().x, b.size().y);
  const int n = 360;
  density_.width = std::max(2, static_cast<int>(std::lround(n * b.size().x / longest)));
  density_.height = std::max(2, static_cast<int>(std::lround(n * b.size().y / longest)));
  std::vector<double> v(static_cast<std::size_t>(density_.width * density_.height));
  for (int y = 0; y < density_.height; ++y)
    for (int x = 0; x < density_.width; ++x) {
      const Vec2 p{b.lo.x + (x + 0.5) * b.size().x / density_.width,
                   b.hi.y - (y + 0.5) * b.size().y / density_.height};
      const double d = (*scenario.density)(p);
      v[static_cast<std::size_t>(y * density_.width + x)] = std::isfinite(d) ? d : 0.0;
    }
  density_max_ = *std::max_element(v.begin(), v.end());
  density_.pixels.reserve(v.size());
  for (double d : v)
    density_.pixels.push_back(density_colour(density_max_ > 0 ? d / density_max_ : 0.0));
}

MapView::MapView(const Scenario& scenario, Vec2 lo, Vec2 hi) : MapView(scenario) {
  place(lo, hi);
}

void MapView::place(Vec2 lo, Vec2 hi) {
  axes_ = map_axes(extent(scenario_), lo, hi);
}

std::vector<std::vector<Vec2>> MapView::to_px(const std::vector<std::vector<Vec2>>& rings) const {
  std::vector<std::vector<Vec2>> out;
  for (const auto& r : rings) {
    out.emplace_back();
    for (Vec2 p : r)
      out.back().push_back(to_px(p));
  }
  return out;
}

void MapView::draw_background(Canvas& c, const Layers& layers, double font) const {
  const Environment& env = *scenario_.environment;
  const auto omega = to_px(env.rings());
  const double u = font / 10;
  c.push_clip({{axes_.lo, {axes_.hi.x, axes_.lo.y}, axes_.hi, {axes_.lo.x, axes_.hi.y}}});
  if (layers.has(Layer::obstacles)) {
    // Everything outside Ω in the frame is obstacle.
    c.rectangle(axes_.lo, axes_.hi, Marks::obstacle());
    c.fill(omega, Colour::hex(0xffffff));
  }
  if (!uniform_ && layers.has(Layer::density)) {
    c.push_clip(omega);
    const Box& b = env.bounds();
    c.image(density_, to_px({b.lo.x, b.hi.y}), to_px({b.hi.x, b.lo.y}));
    c.pop_clip();
  }
  if (layers.has(Layer::obstacles)) c.stroke(omega, Stroke{Colour::hex(0x000000), 0.8 * u});
  c.pop_clip();
  if (layers.has(Layer::axes)) draw_axes(c, axes_, "x [m]", "y [m]", false, font);
}

namespace {
// The colour bar's parts across, in text heights: a gap, the turned label, a gap, the bar, the
// ticks and a gap before their values.
constexpr double kBarGap = 0.7, kBarLabel = 1.2, kBarLabelGap = 0.3, kBar = 0.9, kBarTick = 0.3,
                 kBarValueGap = 0.25;
}  // namespace

std::vector<double> MapView::colour_bar_ticks() const {
  // Counted, not stepped until past the top: a density whose peak the raster missed (a
  // very narrow Gaussian) has no positive maximum, and a step of 0 would never get there.
  std::vector<double> ticks{0.0};
  const double step = tick_step(density_max_, 4);
  if (!(density_max_ > 0) || !std::isfinite(density_max_) || !(step > 0)) return ticks;
  for (int k = 1; k <= 100 && k * step <= density_max_ * (1 + 1e-9); ++k)
    ticks.push_back(k * step);
  return ticks;
}

double MapView::colour_bar_width(double font) const {
  if (uniform_) return 0;
  double widest = 0;
  for (const double v : colour_bar_ticks())
    widest = std::max(widest, text_width(fmt::format("{:g}", v), font));
  return (kBarGap + kBarLabel + kBarLabelGap + kBar + kBarTick + kBarValueGap + 0.2) * font +
         widest;
}

void MapView::draw_colour_bar(Canvas& c, double left, double top, double bottom,
                              double font) const {
  if (uniform_) return;
  const double x0 = left + (kBarGap + kBarLabel + kBarLabelGap) * font, x1 = x0 + kBar * font;
  Image bar{1, 64, {}};
  for (int y = 0; y < bar.height; ++y)
    bar.pixels.push_back(density_colour(1.0 - (y + 0.5) / bar.height));
  c.image(bar, {x0, top}, {x1, bottom});
  const Colour ink = Marks::ink();
  const double u = font / 10;
  c.rectangle({x0, top}, {x1, bottom}, std::nullopt, Stroke{ink, 0.6 * u});
  for (const double v : colour_bar_ticks()) {
    const double y = bottom - (bottom - top) * (density_max_ > 0 ? v / density_max_ : 0.0);
    c.line({x1, y}, {x1 + kBarTick * font, y}, Stroke{ink, 0.6 * u});
    c.text({x1 + (kBarTick + kBarValueGap) * font, y + 0.36 * font}, fmt::format("{:g}", v), font,
           ink);
  }
  // φ's values as the scenario gives them: H is in m⁴·φ (docs/outputs.md).
  c.text({x0 - kBarLabelGap * font - 0.25 * font, (top + bottom) / 2}, "density φ", font, ink,
         Align::centre, 90.0);
}

void MapView::draw_density_swatch(Canvas& c, Vec2 centre, double font) const {
  const Vec2 half{0.8 * font, 0.4 * font};
  if (!uniform_) {
    Image ramp{16, 1, {}};
    for (int x = 0; x < ramp.width; ++x)
      ramp.pixels.push_back(density_colour((x + 0.5) / ramp.width));
    c.image(ramp, centre - half, centre + half);
  } else {
    c.rectangle(centre - half, centre + half, Colour::hex(0xffffff));
  }
  c.rectangle(centre - half, centre + half, std::nullopt, Stroke{Marks::ink(), 0.06 * font});
}

void MapView::draw_scale_bar(Canvas& c, double font) const {
  const Box& b = scenario_.environment->bounds();
  const double len = tick_step(b.size().x, 5), u = font / 10;
  const Vec2 start{axes_.lo.x + font, axes_.hi.y - font};
  const Vec2 end = start + Vec2{len * px_per_metre(), 0};
  const Colour black = Colour::hex(0x000000);
  c.rectangle(start - Vec2{0.4 * font, 1.55 * font}, end + Vec2{0.4 * font, 0.4 * font},
              Colour::hex(0xffffff, 0.8));
  c.line(start, end, Stroke{black, 2.0 * u});
  c.line(start - Vec2{0, 0.3 * font}, start + Vec2{0, 0.3 * font}, Stroke{black, 1.0 * u});
  c.line(end - Vec2{0, 0.3 * font}, end + Vec2{0, 0.3 * font}, Stroke{black, 1.0 * u});
  c.text((start + end) * 0.5 - Vec2{0, 0.45 * font}, fmt::format("{:g} m", len), font, black,
         Align::centre);
}

}  // namespace covsim
