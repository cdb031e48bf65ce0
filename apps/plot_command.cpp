// `covsim plot DIR`: redraws a run's scene and cost figures (SVG, PDF or PNG) from its output
// files, writes DIR/replay.html, a page that plays the run back, and on request a video.
#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "analysis/figures/figures.hpp"
#include "analysis/figures/replay_html.hpp"
#include "analysis/figures/run_video.hpp"
#include "analysis/records/run_files.hpp"
#include "apps/commands.hpp"
#include "apps/figure_options.hpp"
#include "apps/input_error.hpp"
#include "apps/plugin_loader.hpp"
#include "io/atomic_file.hpp"

namespace covsim::app {

namespace {
// A comma-separated list of numbers, each checked by `parse`; errors name the option.
template <class T>
std::vector<T> number_list(const std::string& text, const std::string& option,
                           const std::string& expected) {
  std::vector<T> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    T v{};
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size() ||
        (std::is_floating_point_v<T> && !std::isfinite(static_cast<double>(v))))
      throw InputError(fmt::format("{}: expected {}, found \"{}\"", option, expected, text));
    out.push_back(v);
    start = comma + 1;
  }
  return out;
}
}  // namespace

void add_plot_command(CLI::App& app) {
  struct Options {
    std::string dir, title, window, robots;
    std::size_t frames = 1500;
    bool log_cost = false;
    FigureOptions figures;
    std::vector<std::string> plugins;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "plot", "Redraw a run's scene and cost figures, write replay.html, and make videos");
  cmd->add_option("DIR", o->dir, "Output directory of covsim run")->required();
  o->figures.add_to(cmd, "scene, cost");
  cmd->add_option("--title", o->title, "The scene's title (default: scenario name and outcome)");
  cmd->add_option("--time-window", o->window, "T0,T1: draw the paths between T0 and T1 s");
  cmd->add_option("--robots", o->robots,
                  "I,J,...: draw only these robots' paths and marks; one robot: its planner's "
                  "map and way too (scene, video, and shown first in replay.html)");
  cmd->add_flag("--log-cost", o->log_cost, "The cost figure on a log scale");
  cmd->add_option("--frames", o->frames, "Most frames in replay.html")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1000000}))
      ->capture_default_str();
  add_plugin_option(cmd, o->plugins);
  cmd->callback([o] {
    load_plugins(o->plugins);
    o->figures.check();
    SceneOptions scene_options{o->title, std::nullopt, {}, o->figures.drawn()};
    if (!o->window.empty()) {
      const auto w = number_list<double>(o->window, "--time-window", "T0,T1 in seconds, T0 < T1");
      if (w.size() != 2 || !(w[0] < w[1]) || w[0] < 0)
        throw InputError(fmt::format(
            "--time-window: expected T0,T1 in seconds with 0 <= T0 < T1, found \"{}\"", o->window));
      scene_options.time_window = std::pair{w[0], w[1]};
    }
    if (!o->robots.empty())
      scene_options.robots =
          number_list<std::uint32_t>(o->robots, "--robots", "robot IDs such as 1,4,7");
    const std::filesystem::path d = o->dir;
    const RunFiles run = read_run_files(d);
    if (!run.known.empty()) scene_options.known = &run.known;
    if (!run.planner_maps.empty()) scene_options.planner_maps = &run.planner_maps;
    for (std::uint32_t id : scene_options.robots)
      if (id >= run.outcome.robots.size())
        throw InputError(fmt::format("--robots: robot {} does not exist (the run has {}: 0 to {})",
                                     id, run.outcome.robots.size(), run.outcome.robots.size() - 1));
    const FigureFile file = o->figures.file();
    const std::string ext(extension(file.format));
    AtomicFile scene(d / ("scene." + ext)), cost(d / ("cost." + ext)), replay(d / "replay.html");
    scene.stream() << scene_figure(run.scenario, run.outcome, run.tracks(), scene_options, file);
    cost.stream() << cost_figure(run.samples, run.outcome, o->log_cost, file);
    replay.stream() << replay_html(
        run, o->frames,
        scene_options.robots.size() == 1 ? std::optional(scene_options.robots[0]) : std::nullopt);
    const std::string& video = o->figures.video;
    if (!video.empty()) {
      try {
        VideoOptions settings = o->figures.video_settings();
        if (!run.known.empty()) settings.known = &run.known;
        if (!run.planner_maps.empty() && scene_options.robots.size() == 1) {
          settings.planner_maps = &run.planner_maps;
          settings.planner_robot = scene_options.robots[0];
        }
        write_run_video(run.scenario, run.outcome, run.tracks(), video, settings);
      } catch (const std::runtime_error& e) {
        throw InputError(fmt::format("--video: {}", e.what()));
      }
    }
    scene.commit();
    cost.commit();
    replay.commit();
    fmt::print("wrote {0}/scene.{1}, {0}/cost.{1}, {0}/replay.html{2}\n", d.string(), ext,
               video.empty() ? "" : ", " + video);
  });
}

}  // namespace covsim::app
