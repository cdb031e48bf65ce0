#include "analysis/figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/svg_canvas.hpp"
#include "core/geometry/voronoi_partition.hpp"

namespace covsim {

namespace {
std::vector<std::vector<Vec2>> cell_rings(const VoronoiPartition& p) {
  std::vector<std::vector<Vec2>> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto c = p.cell(i);
    if (c.size() >= 3) out.emplace_back(c.begin(), c.end());
  }
  return out;
}

// A "nice" tick step for a range: 1, 2 or 5 times a power of ten.
double tick_step(double range, int ticks) {
  const double raw = range / ticks;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * p >= raw) return m * p;
  }
  return 10 * p;
}
}  // namespace

std::string scene_svg(const Scenario& scenario, const CoverageOutcome& outcome,
                      const std::vector<std::vector<Vec2>>& real_paths,
                      const std::vector<std::vector<Vec2>>& virtual_paths) {
  const Environment& env = *scenario.environment;
  const Box& b = env.bounds();
  const Vec2 pad = 0.03 * b.size();
  SvgCanvas svg(Box{b.lo - pad, b.hi + pad}, 800, 30);
  svg.raw(fmt::format("<rect width=\"{:.0f}\" height=\"{:.0f}\" fill=\"#ffffff\"/>\n", svg.width(),
                      svg.height()));
  const double unit = svg.scale() * env.diameter() / 1.4142;  // pixels per side of Ω's box, about
  svg.clip_path("omega", env.rings());
  svg.rings({{b.lo - pad,
              {b.hi.x + pad.x, b.lo.y - pad.y},
              b.hi + pad,
              {b.lo.x - pad.x, b.hi.y + pad.y}}},
            "fill:#000000");
  svg.rings(env.rings(), "fill:#ffffff");

  // The density, as yellow shading on a grid.
  const int n = 80;
  const Vec2 cell = b.size() / n;
  std::vector<double> values;
  double vmax = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      values.push_back((*scenario.density)(b.lo + Vec2{(i + 0.5) * cell.x, (j + 0.5) * cell.y}));
      vmax = std::max(vmax, values.back());
    }
  }
  std::string shade = "<g style=\"clip-path:url(#omega)\">\n";
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double v = vmax > 0 ? values[static_cast<std::size_t>(j * n + i)] / vmax : 0.0;
      const Vec2 p = svg.to_px(b.lo + Vec2{i * cell.x, (j + 1) * cell.y});
      shade += fmt::format(
          "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"#ffd21f\" "
          "fill-opacity=\"{:.3f}\"/>\n",
          p.x, p.y, cell.x * svg.scale() + 0.5, cell.y * svg.scale() + 0.5, 0.08 + 0.5 * v);
    }
  }
  svg.raw(shade + "</g>\n");

  // The two final partitions, clipped to Ω.
  const CellIntegrator integrator(env, *scenario.density);
  std::vector<Vec2> virt, real;
  for (const RobotOutcome& r : outcome.robots) {
    virt.push_back(r.virtual_generator);
    real.push_back(r.position);
  }
  const auto share = VoronoiPartition::Coincident::share;  // robots at one place share a cell
  const VoronoiPartition virtual_partition(integrator, virt, share);
  const VoronoiPartition real_partition(integrator, real, share);
  const double line = std::max(1.0, unit / 400);
  svg.raw("<g style=\"clip-path:url(#omega)\">\n");
  for (const auto& c : cell_rings(virtual_partition)) {
    svg.rings({c}, fmt::format("fill:none;stroke:#1f5fbf;stroke-width:{:.2f}", 1.5 * line));
  }
  for (const auto& c : cell_rings(real_partition)) {
    svg.rings({c}, fmt::format("fill:none;stroke:#d62728;stroke-width:{:.2f};stroke-dasharray:6,4",
                               1.5 * line));
  }
  svg.raw("</g>\n");

  for (const auto& p : virtual_paths) {
    svg.polyline(p, fmt::format("stroke:#2ca02c;stroke-width:{:.2f};stroke-dasharray:4,3", line));
  }
  for (const auto& p : real_paths)
    svg.polyline(p, fmt::format("stroke:#1a1a6e;stroke-width:{:.2f}", 1.5 * line));
  const double mark = std::max(4.0, unit / 80);
  for (std::size_t i = 0; i < outcome.robots.size(); ++i) {
    const RobotOutcome& r = outcome.robots[i];
    if (!real_paths.empty())
      svg.circle(real_paths[i].front(), mark * 0.7, "fill:#ffffff;stroke:#1a1a6e;stroke-width:1.5");
    svg.cross(r.virtual_target, mark * 0.8, "stroke:#d62728;stroke-width:2");
    if (r.projected) svg.cross(r.real_target, mark, "stroke:#000000;stroke-width:4");
    if (r.projected) svg.cross(r.real_target, mark, "stroke:#ffd21f;stroke-width:2");
    svg.circle(r.position, mark * 0.7, "fill:#1f5fbf;stroke:#ffffff;stroke-width:1");
  }
  svg.text({30, 20},
           fmt::format("{}: {} robots, {} at t = {:.1f} s; H real {:.4g}, H virtual {:.4g}",
                       scenario.source, outcome.robots.size(),
                       outcome.converged ? "converged" : "stopped", outcome.sim_time.seconds(),
                       outcome.cost_real, outcome.cost_virtual),
           "font-size:13px;fill:#222222");
  return svg.str();
}

std::string cost_svg(const std::vector<MetricsSample>& samples) {
  const double w = 640, h = 400, left = 70, right = 20, top = 30, bottom = 50;
  double tmax = 1e-9, cmax = 0.0;
  for (const MetricsSample& s : samples) {
    tmax = std::max(tmax, s.t);
    cmax = std::max({cmax, s.cost_real, s.cost_virtual});
  }
  if (!(cmax > 0)) cmax = 1.0;
  const double ts = tick_step(tmax, 8), cs = tick_step(cmax, 6);
  tmax = std::ceil(tmax / ts) * ts;
  cmax = std::ceil(cmax / cs) * cs;
  const auto X = [&](double t) { return left + (w - left - right) * t / tmax; };
  const auto Y = [&](double c) { return h - bottom - (h - top - bottom) * c / cmax; };
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"{0}\" height=\"{1}\" "
      "fill=\"#ffffff\"/>\n",
      w, h);
  for (double t = 0; t <= tmax + 1e-9 * ts; t += ts) {
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#e0e0e0\"/>\n",
        X(t), Y(0), Y(cmax));
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:g}</text>\n", X(t),
                       Y(0) + 16, t);
  }
  for (double c = 0; c <= cmax + 1e-9 * cs; c += cs) {
    out += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#e0e0e0\"/>\n",
        X(0), Y(c), X(tmax));
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:g}</text>\n",
                       X(0) - 6, Y(c) + 4, c);
  }
  out += fmt::format(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
      "stroke=\"#000\"/>\n",
      X(0), Y(cmax), X(tmax) - X(0), Y(0) - Y(cmax));
  const auto series = [&](auto value, const char* colour, const char* dash) {
    std::string pts;
    for (const MetricsSample& s : samples)
      pts += fmt::format("{:.2f},{:.2f} ", X(s.t), Y(value(s)));
    return fmt::format(
        "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" stroke-dasharray=\"{}\" "
        "points=\"{}\"/>\n",
        colour, dash, pts);
  };
  out += series([](const MetricsSample& s) { return s.cost_real; }, "#d62728", "none");
  out += series([](const MetricsSample& s) { return s.cost_virtual; }, "#1f5fbf", "6,4");
  out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">time [s]</text>\n",
                     (X(0) + X(tmax)) / 2, h - 12);
  out += fmt::format(
      "<text x=\"16\" y=\"{:.1f}\" text-anchor=\"middle\" transform=\"rotate(-90 16 {:.1f})\">cost "
      "H</text>\n",
      (Y(0) + Y(cmax)) / 2, (Y(0) + Y(cmax)) / 2);
  out += fmt::format(
      "<line x1=\"{0:.1f}\" y1=\"20\" x2=\"{1:.1f}\" y2=\"20\" stroke=\"#d62728\" "
      "stroke-width=\"2\"/><text x=\"{2:.1f}\" "
      "y=\"24\">real generators</text>\n<line x1=\"{3:.1f}\" y1=\"20\" x2=\"{4:.1f}\" y2=\"20\" "
      "stroke=\"#1f5fbf\" "
      "stroke-width=\"2\" stroke-dasharray=\"6,4\"/><text x=\"{5:.1f}\" y=\"24\">virtual "
      "generators</text>\n",
      w - 330, w - 300, w - 294, w - 170, w - 140, w - 134);
  return out + "</svg>\n";
}

}  // namespace covsim
