#include "analysis/figures/figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "analysis/figures/line_chart.hpp"
#include "analysis/figures/map_legend.hpp"
#include "analysis/figures/planner_map_view.hpp"
#include "analysis/figures/robot_palette.hpp"
#include "analysis/figures/unknown_area.hpp"
#include "analysis/records/measure.hpp"
#include "analysis/records/run_files.hpp"
#include "geometry/voronoi_partition.hpp"

namespace covsim {

std::string scenario_name(const std::string& source) {
  const std::string stem = std::filesystem::path(source).stem().string();
  return stem.empty() ? source : stem;
}

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

std::string scene_figure(const Scenario& scenario, const CoverageOutcome& outcome,
                         const std::vector<RobotTrack>& tracks, const SceneOptions& options,
                         const FigureFile& file) {
  const Environment& env = *scenario.environment;
  const double radius = scenario.coverage.radius;  // bodies drawn to scale
  const Layers& layers = options.layers;
  const double f = file.size.font, pad = 0.6 * f;
  const Marks marks{file.size.unit()};

  std::set<std::uint32_t> shown(options.robots.begin(), options.robots.end());
  const auto drawn = [&](std::size_t i) {
    return shown.empty() || shown.count(static_cast<std::uint32_t>(i));
  };
  const double t0 = options.time_window ? options.time_window->first : -INFINITY;
  const double t1 = options.time_window ? options.time_window->second : INFINITY;
  const bool planner_map = options.planner_maps != nullptr && !options.planner_maps->empty() &&
                           options.robots.size() == 1;
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

  std::string title = options.title;
  if (title.empty()) {
    title =
        fmt::format("{}: {} robot{}, {} at t = {:.1f} s; H real {:.4g}, virtual {:.4g} {}",
                    scenario_name(scenario.source), outcome.robots.size(),
                    outcome.robots.size() == 1 ? "" : "s",
                    outcome.converged ? "converged" : "stopped (" + outcome.stop_reason + ")",
                    outcome.sim_time.seconds(), outcome.cost_real, outcome.cost_virtual, kCostUnit);
    if (options.time_window)
      title += fmt::format(" (paths {:g}-{:g} s)", options.time_window->first,
                           options.time_window->second);
  }

  // Laid out before drawing: the title's lines, the room the axes' labels take, the colour
  // bar, and the legend under the map (or beside it on a slide, whose height is fixed).
  const double w = file.size.width, title_font = f + 1;
  const std::vector<std::string> title_lines = layers.has(Layer::title)
                                                   ? wrap_text(title, title_font, w - 2 * pad)
                                                   : std::vector<std::string>{};
  const double top =
      pad + (title_lines.empty() ? 0 : 1.3 * title_font * title_lines.size() + 0.3 * f);
  MapView view(scenario);
  const bool axes = layers.has(Layer::axes);
  const double left = axes ? axes_left_room(view.axes(), f) : pad;
  const double bottom = axes ? axes_bottom_room(f) : pad;
  const double bar = layers.has(Layer::density) ? view.colour_bar_width(f) : 0;
  const Legend legend =
      layers.has(Layer::legend)
          ? map_legend(layers, marks, view, f, options.known != nullptr && !options.known->empty(),
                       planner_map)
          : Legend({}, f);
  const double aspect = MapView::aspect(scenario);
  const bool beside = file.size.height > 0;
  double map_w = w - left - bar - pad, h = file.size.height;
  int columns = 1;
  if (beside) {
    if (!legend.empty()) map_w -= legend.entry_width() + 2 * pad;
    map_w = std::max(10.0, std::min(map_w, (h - top - bottom) / aspect));
  } else {
    columns = legend.columns_within(w - 2 * pad);
    h = top + map_w * aspect + bottom + (legend.empty() ? 0 : legend.size(columns).y + pad);
  }
  const double map_h = map_w * aspect;
  view.place({left, top}, {left + map_w, top + map_h});

  Canvas c(file, w, h);
  c.rectangle({0, 0}, {w, h}, Colour::hex(0xffffff));
  view.draw_background(c, layers, f);

  // What the robots' maps did not yet hold at that time, shaded over Ω.
  if (options.known != nullptr && layers.has(Layer::obstacles))
    // One robot drawn, whose own map was kept: its map; else the robots' maps together.
    shade_unknown(c, view, *options.known, t1,
                  options.robots.size() == 1 && options.robots[0] < options.known->robots.size()
                      ? std::optional<std::uint32_t>(options.robots[0])
                      : std::nullopt);
  // The two partitions at that time, clipped to Ω.
  const CellIntegrator integrator(env, *scenario.density);
  std::vector<Vec2> virt, real;
  for (const RobotOutcome& r : state) {
    virt.push_back(r.virtual_generator);
    real.push_back(r.position);
  }
  const auto split = VoronoiPartition::Coincident::split;  // as the controller splits them
  c.push_clip(view.to_px(env.rings()));
  if (!state.empty() && layers.has(Layer::cells))
    for (const auto& cell : cell_rings(VoronoiPartition(integrator, virt, split)))
      c.stroke(view.to_px({cell}), marks.cells());
  if (!state.empty() && layers.has(Layer::real_cells))
    for (const auto& cell : cell_rings(VoronoiPartition(integrator, real, split)))
      c.stroke(view.to_px({cell}), marks.real_cells());
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
    if (layers.has(Layer::virtual_paths)) c.polyline(vp, marks.virtual_path(col));
    if (layers.has(Layer::paths)) c.polyline(rp, marks.path(col));
  }

  // One robot drawn whose planner kept a map: its walls (dark orange) and its way ahead.
  if (planner_map) {
    const std::uint32_t robot = options.robots[0];
    const PlannerPicture p =
        options.planner_maps->at(robot, std::isfinite(t1) ? t1 : outcome.sim_time.seconds());
    draw_planner_map(c, view, marks, p, robot_colour(robot));
  }

  for (std::size_t i = 0; i < state.size(); ++i) {
    if (!drawn(i)) continue;
    const RobotOutcome& r = state[i];
    const Colour col = robot_colour(i);
    if (layers.has(Layer::paths) && i < tracks.size() && !tracks[i].t.empty()) {
      const auto [first, last] = tracks[i].window(t0, t1);
      if (first < last) marks.start(c, view.to_px(tracks[i].position[first]), col);
    }
    if (layers.has(Layer::targets)) marks.target(c, view.to_px(r.virtual_target));
    if (layers.has(Layer::generators)) marks.generator(c, view.to_px(r.virtual_generator), col);
    if (layers.has(Layer::targets) && r.projected)
      marks.projected_target(c, view.to_px(r.real_target));
    const Vec2 p = view.to_px(r.position);
    if (layers.has(Layer::robots)) marks.body(c, p, radius * view.px_per_metre(), col);
    if (layers.has(Layer::ids)) marks.id(c, p, i, 0.9 * f);
  }
  if (axes) view.draw_scale_bar(c, f);

  for (std::size_t k = 0; k < title_lines.size(); ++k)
    c.text({pad, pad + title_font * (1.3 * k + 1.0)}, title_lines[k], title_font, Marks::ink());
  if (bar > 0) view.draw_colour_bar(c, left + map_w, top, top + map_h, f);
  if (!legend.empty())
    legend.draw(c, beside ? Vec2{left + map_w + bar + pad, top} : Vec2{pad, top + map_h + bottom},
                columns);
  return c.finish();
}

std::string cost_figure(const std::vector<MetricsSample>& samples, const CoverageOutcome& outcome,
                        bool log_y, const FigureFile& file) {
  LineChart chart;
  chart.title = "Cost of the real and the virtual generators";
  chart.x_label = "time [s]";
  chart.y_label = fmt::format("cost H [{}]", kCostUnit);
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
