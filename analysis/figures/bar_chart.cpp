#include "analysis/figures/bar_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/figures/axes.hpp"

namespace covsim {

std::string draw_bar_chart(const BarChart& chart, const FigureFile& file) {
  static constexpr std::uint32_t kPalette[] = {0x1f5fbf, 0xd9822b, 0x3a9a4a, 0x9467bd,
                                               0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22};
  const double w = 720, h = 400, left = 70, right = 20, top = 40, bottom = 80;
  double most = 0.0;
  for (const auto& row : chart.values)
    for (const auto& v : row)
      if (v && std::isfinite(*v)) most = std::max(most, *v);
  if (!(most > 0)) most = 1.0;
  Canvas c(file, w, h);
  const Colour ink = Colour::hex(0x222222);
  c.rectangle({0, 0}, {w, h}, Colour::hex(0xffffff));
  c.text({left, 22}, chart.title, 14, ink);
  const double step = tick_step(most, 5), top_value = std::ceil(most / step) * step;
  const auto y_of = [&](double v) { return h - bottom - (h - top - bottom) * v / top_value; };
  for (double v = 0; v <= top_value * (1 + 1e-9); v += step) {
    c.line({left, y_of(v)}, {w - right, y_of(v)}, Stroke{Colour::hex(0xdddddd), 0.8});
    c.text({left - 6, y_of(v) + 4}, fmt::format("{:g}", v), 11, ink, Align::right);
  }
  c.text({18, (top + h - bottom) / 2}, chart.y_label, 12, ink, Align::centre, 90.0);
  const std::size_t ng = std::max<std::size_t>(1, chart.groups.size());
  const std::size_t ns = std::max<std::size_t>(1, chart.series.size());
  const double gw = (w - left - right) / static_cast<double>(ng);
  const double bw = gw / static_cast<double>(ns + 1);
  for (std::size_t g = 0; g < chart.groups.size(); ++g) {
    const double x0 = left + static_cast<double>(g) * gw + bw / 2;
    c.text({x0 + static_cast<double>(ns) * bw / 2, h - bottom + 18}, chart.groups[g], 11, ink,
           Align::centre);
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      const auto& v = g < chart.values.size() && s < chart.values[g].size()
                          ? chart.values[g][s]
                          : std::optional<double>{};
      if (!v || !std::isfinite(*v)) continue;
      const double x = x0 + static_cast<double>(s) * bw;
      c.rectangle({x, y_of(std::max(0.0, *v))}, {x + 0.9 * bw, y_of(0)},
                  Colour::hex(kPalette[s % 8]));
    }
  }
  c.line({left, y_of(0)}, {w - right, y_of(0)}, Stroke{ink, 0.8});
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    const double x = left + static_cast<double>(s) * 200;
    c.rectangle({x, h - 32}, {x + 12, h - 20}, Colour::hex(kPalette[s % 8]));
    c.text({x + 18, h - 21}, chart.series[s], 12, ink);
  }
  return c.finish();
}

}  // namespace covsim
