#include "analysis/figures/map_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

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

Colour robot_colour(std::size_t i) {
  // Tableau's 20 colours, dark ones first.
  static constexpr std::array<std::uint32_t, 20> palette = {
      0x1f77b4, 0xd62728, 0x2ca02c, 0x9467bd, 0x8c564b, 0xe377c2, 0x17becf,
      0x7f7f7f, 0xbcbd22, 0xff7f0e, 0x393b79, 0x637939, 0x8c6d31, 0x843c39,
      0x7b4173, 0x3182bd, 0xe6550d, 0x31a354, 0x756bb1, 0x636363};
  return Colour::hex(palette[i % palette.size()]);
}

MapView::MapView(const Scenario& scenario, Vec2 lo, Vec2 hi) : scenario_(scenario) {
  const Box& b = scenario.environment->bounds();
  const Vec2 pad = 0.03 * b.size();
  axes_ = map_axes(Box{b.lo - pad, b.hi + pad}, lo, hi);
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

std::vector<std::vector<Vec2>> MapView::to_px(const std::vector<std::vector<Vec2>>& rings) const {
  std::vector<std::vector<Vec2>> out;
  for (const auto& r : rings) {
    out.emplace_back();
    for (Vec2 p : r)
      out.back().push_back(to_px(p));
  }
  return out;
}

void MapView::draw_background(Canvas& c) const {
  const Environment& env = *scenario_.environment;
  const auto omega = to_px(env.rings());
  // Everything outside Ω in the frame is obstacle.
  c.push_clip({{axes_.lo, {axes_.hi.x, axes_.lo.y}, axes_.hi, {axes_.lo.x, axes_.hi.y}}});
  c.rectangle(axes_.lo, axes_.hi, Colour::hex(0x4a4a4a));
  c.fill(omega, Colour::hex(0xffffff));
  if (!uniform_) {
    c.push_clip(omega);
    const Box& b = env.bounds();
    c.image(density_, to_px({b.lo.x, b.hi.y}), to_px({b.hi.x, b.lo.y}));
    c.pop_clip();
  }
  c.stroke(omega, Stroke{Colour::hex(0x000000), 0.8});
  c.pop_clip();
  draw_axes(c, axes_, "x [m]", "y [m]", false);
}

void MapView::draw_colour_bar(Canvas& c, Vec2 lo, Vec2 hi) const {
  if (uniform_) return;
  Image bar{1, 64, {}};
  for (int y = 0; y < bar.height; ++y)
    bar.pixels.push_back(density_colour(1.0 - (y + 0.5) / bar.height));
  c.image(bar, lo, hi);
  const Colour ink = Colour::hex(0x222222);
  c.rectangle(lo, hi, std::nullopt, Stroke{ink, 0.6});
  const double step = tick_step(density_max_, 4);
  for (double v = 0; v <= density_max_ * (1 + 1e-9); v += step) {
    const double y = hi.y - (hi.y - lo.y) * v / density_max_;
    c.line({hi.x, y}, {hi.x + 3, y}, Stroke{ink, 0.6});
    c.text({hi.x + 5, y + 3.5}, fmt::format("{:g}", v), 9, ink);
  }
  c.text({lo.x - 6, (lo.y + hi.y) / 2}, "density φ [weight / m²]", 10, ink, Align::centre, 90.0);
}

void MapView::draw_scale_bar(Canvas& c) const {
  const Box& b = scenario_.environment->bounds();
  const double len = tick_step(b.size().x, 5);
  const Vec2 start{axes_.lo.x + 10, axes_.hi.y - 10};
  const Vec2 end = start + Vec2{len * px_per_metre(), 0};
  c.rectangle(start - Vec2{4, 16}, end + Vec2{4, 4}, Colour::hex(0xffffff, 0.8));
  c.line(start, end, Stroke{Colour::hex(0x000000), 2.0});
  c.line(start - Vec2{0, 3}, start + Vec2{0, 3}, Stroke{Colour::hex(0x000000), 1.0});
  c.line(end - Vec2{0, 3}, end + Vec2{0, 3}, Stroke{Colour::hex(0x000000), 1.0});
  c.text((start + end) * 0.5 - Vec2{0, 5}, fmt::format("{:g} m", len), 9, Colour::hex(0x000000),
         Align::centre);
}

}  // namespace covsim
