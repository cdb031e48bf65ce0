#include "analysis/figures/figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <set>

#include "analysis/figures/line_chart.hpp"
#include "analysis/figures/map_view.hpp"
#include "analysis/records/run_files.hpp"
#include "geometry/voronoi_partition.hpp"

namespace covsim {

std::string scenario_name(const std::string& source) {
  const std::string stem = std::filesystem::path(source).stem().string();
  return stem.empty() ? source : stem;
}

namespace {
const Colour kInk = Colour::hex(0x222222);
const Colour kVirtualCells = Colour::hex(0x1f5fbf), kRealCells = Colour::hex(0xd62728);
const Colour kProjected = Colour::hex(0xffd21f);

std::vector<std::vector<Vec2>> cell_rings(const VoronoiPartition& p) {
  std::vector<std::vector<Vec2>> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto c = p.cell(i);
    if (c.size() >= 3) out.emplace_back(c.begin(), c.end());
  }
  return out;
}

// One legend row: a symbol drawn by `symbol` at the row's left, then the label.
struct Legend {
  Canvas& c;
  Vec2 at;
  void row(const std::string& label, const std::function<void(Vec2)>& symbol) {
    symbol(at + Vec2{8, -4});
    c.text(at + Vec2{22, 0}, label, 10, kInk);
    at.y += 15;
  }
};
}  // namespace

std::string scene_figure(const Scenario& scenario, const CoverageOutcome& outcome,
                         const std::vector<RobotTrack>& tracks, const SceneOptions& options,
                         const FigureFile& file) {
  const Environment& env = *scenario.environment;
  const Box& b = env.bounds();
  // The map's rectangle keeps Ω's aspect; the legend and colour bar sit to its right.
  const double map_w = 620, aspect = std::clamp(b.size().y / b.size().x, 0.3, 1.6);
  const double left = 56, top = 40, bottom = 48, side = 200;
  const double map_h = map_w * aspect;
  const double w = left + map_w + side, h = top + map_h + bottom;
  Canvas c(file, w, h);
  c.rectangle({0, 0}, {w, h}, Colour::hex(0xffffff));
  const MapView view(scenario, {left, top}, {left + map_w, top + map_h});
  view.draw_background(c);

  std::set<std::uint32_t> shown(options.robots.begin(), options.robots.end());
  const auto drawn = [&](std::size_t i) {
    return shown.empty() || shown.count(static_cast<std::uint32_t>(i));
  };
  const double t0 = options.time_window ? options.time_window->first : -INFINITY;
  const double t1 = options.time_window ? options.time_window->second : INFINITY;
  // Where each robot stands at the figure's time: the run's end, or the window's.
  std::vector<RobotOutcome> state = outcome.robots;
  if (options.time_window)
    for (std::size_t i = 0; i < state.size() && i < tracks.size(); ++i) {
      const RobotTrack& k = tracks[i];
      if (k.t.empty()) continue;
      const std::size_t j = k.at(t1);
      state[i].position = k.position[j];
      state[i].virtual_generator = k.virtual_generator[j];
      state[i].virtual_target = k.virtual_target[j];
      state[i].real_target = k.real_target[j];
      state[i].projected = !env.contains(k.virtual_target[j]);
    }

  // The two partitions at that time, clipped to Ω.
  const CellIntegrator integrator(env, *scenario.density);
  std::vector<Vec2> virt, real;
  for (const RobotOutcome& r : state) {
    virt.push_back(r.virtual_generator);
    real.push_back(r.position);
  }
  const auto split = VoronoiPartition::Coincident::split;  // as the controller splits them
  const double scale = std::clamp(view.px_per_metre() * env.diameter() / 900.0, 0.6, 1.2);
  c.push_clip(view.to_px(env.rings()));
  if (!state.empty()) {
    for (const auto& cell : cell_rings(VoronoiPartition(integrator, virt, split)))
      c.stroke(view.to_px({cell}), Stroke{kVirtualCells, 1.2 * scale});
    for (const auto& cell : cell_rings(VoronoiPartition(integrator, real, split)))
      c.stroke(view.to_px({cell}), Stroke{kRealCells, 1.2 * scale, {5.0, 3.0}});
  }
  c.pop_clip();
  // Paths: the virtual generator's thin and dashed, the robot's solid, in its colour. Above
  // the obstacles, unclipped: a walk along a wall lies on ∂Ω, where a clip to Ω would hide
  // half of it, and a virtual generator crosses obstacles (it moves as if there were none).
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    if (!drawn(i)) continue;
    const RobotTrack& k = tracks[i];
    const auto [first, last] = k.window(t0, t1);
    std::vector<Vec2> vp, rp;
    for (std::size_t j = first; j < last; ++j) {
      const Vec2 v = view.to_px(k.virtual_generator[j]), r = view.to_px(k.position[j]);
      if (vp.empty() || distance(vp.back(), v) > 0.8) vp.push_back(v);
      if (rp.empty() || distance(rp.back(), r) > 0.8) rp.push_back(r);
    }
    if (last > first) {  // the decimation keeps the end
      vp.push_back(view.to_px(k.virtual_generator[last - 1]));
      rp.push_back(view.to_px(k.position[last - 1]));
    }
    const Colour col = robot_colour(i);
    c.polyline(vp, Stroke{Colour{col.r, col.g, col.b, 0.6}, 0.8 * scale, {3.0, 2.5}});
    c.polyline(rp, Stroke{col, 1.6 * scale});
  }

  const double mark = 4.0 * scale;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (!drawn(i)) continue;
    const RobotOutcome& r = state[i];
    const Colour col = robot_colour(i);
    if (i < tracks.size() && !tracks[i].t.empty()) {
      const auto [first, last] = tracks[i].window(t0, t1);
      if (first < last)
        c.circle(view.to_px(tracks[i].position[first]), mark, Colour::hex(0xffffff),
                 Stroke{col, 1.3});
    }
    c.cross(view.to_px(r.virtual_target), mark * 0.9, Stroke{kInk, 1.2});
    c.square(view.to_px(r.virtual_generator), mark * 0.6, col, Stroke{Colour::hex(0xffffff), 0.6});
    if (r.projected) {
      c.cross(view.to_px(r.real_target), mark * 1.3, Stroke{Colour::hex(0x000000), 3.2});
      c.cross(view.to_px(r.real_target), mark * 1.3, Stroke{kProjected, 1.6});
    }
    const Vec2 p = view.to_px(r.position);
    c.circle(p, mark, col, Stroke{Colour::hex(0xffffff), 1.0});
    c.text(p + Vec2{mark + 1.5, -mark - 1}, std::to_string(i), 8.5 * scale + 1.5, kInk);
  }
  view.draw_scale_bar(c);

  // Title, legend and colour bar.
  std::string title = options.title;
  if (title.empty()) {
    title = fmt::format("{}: {} robots, {} at t = {:.1f} s; H real {:.4g}, virtual {:.4g}",
                        scenario_name(scenario.source), outcome.robots.size(),
                        outcome.converged ? "converged" : "stopped (" + outcome.stop_reason + ")",
                        outcome.sim_time.seconds(), outcome.cost_real, outcome.cost_virtual);
    if (options.time_window)
      title += fmt::format(" (paths {:g}-{:g} s)", options.time_window->first,
                           options.time_window->second);
  }
  c.text({left, 22}, title, 12, kInk);
  Legend legend{c, {left + map_w + 24, top + 10}};
  const Colour sample = robot_colour(0);
  legend.row("robot path (colour per robot)", [&](Vec2 p) {
    c.line(p - Vec2{8, 0}, p + Vec2{8, 0}, Stroke{sample, 1.6});
  });
  legend.row("virtual generator path", [&](Vec2 p) {
    c.line(p - Vec2{8, 0}, p + Vec2{8, 0}, Stroke{sample, 0.8, {3.0, 2.5}});
  });
  legend.row("start", [&](Vec2 p) { c.circle(p, 4, Colour::hex(0xffffff), Stroke{sample, 1.3}); });
  legend.row("robot (ID)", [&](Vec2 p) { c.circle(p, 4, sample); });
  legend.row("virtual generator", [&](Vec2 p) { c.square(p, 2.6, sample); });
  legend.row("virtual target", [&](Vec2 p) { c.cross(p, 3.6, Stroke{kInk, 1.2}); });
  legend.row("projected real target", [&](Vec2 p) {
    c.cross(p, 5, Stroke{Colour::hex(0x000000), 3.2});
    c.cross(p, 5, Stroke{kProjected, 1.6});
  });
  legend.row("cells of virtual generators", [&](Vec2 p) {
    c.line(p - Vec2{8, 0}, p + Vec2{8, 0}, Stroke{kVirtualCells, 1.2});
  });
  legend.row("cells of real positions", [&](Vec2 p) {
    c.line(p - Vec2{8, 0}, p + Vec2{8, 0}, Stroke{kRealCells, 1.2, {5.0, 3.0}});
  });
  legend.row("obstacle", [&](Vec2 p) {
    c.rectangle(p - Vec2{7, 5}, p + Vec2{7, 5}, Colour::hex(0x4a4a4a));
  });
  if (view.uniform()) legend.row("density φ uniform", [](Vec2) {});
  const double bar_top = legend.at.y + 14;
  if (top + map_h - bar_top > 60)
    view.draw_colour_bar(c, {left + map_w + 40, bar_top}, {left + map_w + 52, top + map_h});
  return c.finish();
}

std::string cost_figure(const std::vector<MetricsSample>& samples, const CoverageOutcome& outcome,
                        bool log_y, const FigureFile& file) {
  LineChart chart;
  chart.title = "Cost of the real and the virtual generators";
  chart.x_label = "time [s]";
  chart.y_label = "cost H [weight · m²]";
  chart.log_y = log_y;
  ChartSeries real{"H of the real positions", {}, false, false, {}},
      virt{"H of the virtual generators", {}, false, true, {}};
  for (const MetricsSample& s : samples) {
    real.points.push_back({s.t, s.cost_real});
    virt.points.push_back({s.t, s.cost_virtual});
  }
  chart.series = {real, virt};
  if (outcome.converged)
    chart.marker = {outcome.sim_time.seconds(),
                    fmt::format("converged at {:.1f} s", outcome.sim_time.seconds())};
  return draw_line_chart(chart, file);
}

bool is_run_output(const std::string& name) {
  if (is_record_file(name) || name == "replay.html") return true;
  for (const char* stem : {"scene.", "cost."})
    for (FigureFormat format : {FigureFormat::svg, FigureFormat::pdf, FigureFormat::png})
      if (name == stem + std::string(extension(format))) return true;
  return false;
}

}  // namespace covsim
