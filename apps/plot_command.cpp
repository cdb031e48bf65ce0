// `covsim plot DIR`: redraws a run's scene.svg and cost.svg from its output files, and
// writes DIR/replay.html, a page that plays the run back.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>

#include "analysis/figures.hpp"
#include "analysis/replay_html.hpp"
#include "analysis/run_files.hpp"
#include "apps/commands.hpp"
#include "apps/plugin_loader.hpp"
#include "core/atomic_file.hpp"

namespace covsim::app {

void add_plot_command(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto frames = std::make_shared<std::size_t>(1500);
  CLI::App* cmd = app.add_subcommand(
      "plot", "Redraw a run's scene.svg and cost.svg, and write replay.html to play it back");
  cmd->add_option("DIR", *dir, "Output directory of covsim run")->required();
  cmd->add_option("--frames", *frames, "Most frames in replay.html")->capture_default_str();
  auto plugins = std::make_shared<std::vector<std::string>>();
  add_plugin_option(cmd, *plugins);
  cmd->callback([dir, frames, plugins] {
    load_plugins(*plugins);
    const std::filesystem::path d = *dir;
    const RunFiles run = read_run_files(d);
    AtomicFile scene(d / "scene.svg"), cost(d / "cost.svg"), replay(d / "replay.html");
    scene.stream() << scene_svg(run.scenario, run.outcome, run.real_paths(), run.virtual_paths());
    cost.stream() << cost_svg(run.samples);
    replay.stream() << replay_html(run, *frames);
    scene.commit();
    cost.commit();
    replay.commit();
    fmt::print("wrote {0}/scene.svg, {0}/cost.svg, {0}/replay.html\n", d.string());
  });
}

}  // namespace covsim::app
