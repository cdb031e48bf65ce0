#include "analysis/figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/line_chart.hpp"
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
  const auto split = VoronoiPartition::Coincident::split;  // as the controller splits them
  const VoronoiPartition virtual_partition(integrator, virt, split);
  const VoronoiPartition real_partition(integrator, real, split);
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
  ChartSeries real{"real generators", {}, false, false, {}},
      virt{"virtual generators", {}, false, true, {}};
  for (const MetricsSample& s : samples) {
    real.points.push_back({s.t, s.cost_real});
    virt.points.push_back({s.t, s.cost_virtual});
  }
  return line_chart_svg("Cost of the real and the virtual generators", "time [s]", "cost H",
                        {real, virt});
}

}  // namespace covsim
