// `covsim run SCENARIO [--seed N] [--set PATH=VALUE ...] [--out DIR] [--compress]`: runs the
// scenario and writes scenario.json, final.json, trajectory.csv (trajectory.csv.gz with
// --compress or "recording": {"compress": true}), metrics.csv, scene and cost figures into
// DIR (default out/<scenario name>-<seed>), all of them only if the run succeeds; with
// --video, a video of the run once DIR is in place. The figures' and the video's options are
// covsim plot's.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>

#include "analysis/figures/figures.hpp"
#include "analysis/figures/run_video.hpp"
#include "analysis/records/final_json.hpp"
#include "analysis/records/run_files.hpp"
#include "analysis/records/run_recorder.hpp"
#include "apps/commands.hpp"
#include "apps/figure_options.hpp"
#include "apps/input_error.hpp"
#include "apps/output_guard.hpp"
#include "apps/plugin_loader.hpp"
#include "apps/scenario_options.hpp"
#include "core/fingerprint.hpp"
#include "core/trace.hpp"
#include "io/atomic_file.hpp"
#include "io/staged_folder.hpp"
#include "scenarios/readable_json.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/coverage_run.hpp"
#include "sim/run_progress.hpp"
#include "sim/trace_replay.hpp"

namespace covsim::app {

namespace fs = std::filesystem;

void add_run_command(CLI::App& app) {
  struct Options {
    ScenarioOptions scenario;
    std::string out;
    std::string trace;
    FigureOptions figures;
    bool compress = false;
    std::vector<std::string> plugins;
  };
  auto opts = std::make_shared<Options>();
  CLI::App* cmd =
      app.add_subcommand("run", "Run the coverage controller on a scenario and write its outputs");
  opts->scenario.add_to(cmd, "Scenario file");
  cmd->add_option("--out", opts->out,
                  "Output directory, created if missing (default out/<scenario name>-<seed>)");
  cmd->add_option("--trace", opts->trace, "Also write the event trace to this file");
  opts->figures.add_to(cmd, "scene, cost");
  cmd->add_flag("--compress", opts->compress,
                "Write trajectory.csv.gz (gzip) instead of trajectory.csv, as "
                "\"recording\": {\"compress\": true} does");
  add_plugin_option(cmd, opts->plugins);
  cmd->callback([opts] {
    load_plugins(opts->plugins);
    opts->figures.check();  // before the run: a bad option must not cost one
    const Scenario scenario = opts->scenario.load();
    if (scenario.robot_positions.empty())
      throw ScenarioError(scenario.source, "$", "missing required key \"robots\"");
    if (!scenario.seed)
      throw ScenarioError(scenario.source, "$",
                          "missing required key \"seed\" (or give one with --seed)");
    fs::path dir =
        !opts->out.empty()
            ? fs::path(opts->out).lexically_normal()
            : fs::path("out") / fmt::format("{}-{}", fs::path(opts->scenario.file).stem().string(),
                                            *scenario.seed);
    if (!dir.has_filename()) dir = dir.parent_path();  // "out/run/"
    // One writer at a time, before anything in or beside DIR is touched.
    const auto lock = guard_output(dir);
    // The run folder appears whole or not at all: written as DIR.partial and put in place
    // at the end, over an existing DIR by one atomic exchange (what the earlier run wrote
    // goes; other files stay).
    std::error_code ec;
    if (fs::is_directory(dir, ec)) {
      // Partial files a killed `covsim plot` left behind.
      for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.path().extension() == ".partial") fs::remove(entry.path(), ec);
    }
    std::unique_ptr<StagedFolder> folder;
    try {
      folder = std::make_unique<StagedFolder>(dir, is_run_output);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
    const fs::path work = folder->path();
    std::unique_ptr<TraceWriter> trace;
    if (!opts->trace.empty()) {
      const TraceHeader header =
          trace_header_for(scenario, fs::path(opts->scenario.file).parent_path());
      trace = std::make_unique<TraceWriter>(opts->trace, header);
    }
    RecordingConfig recording = scenario.recording;
    recording.compress = recording.compress || opts->compress;
    RunRecorder recorder(work, scenario.robot_positions, recording,
                         track_tolerance(scenario.environment->diameter()));
    RunProgress progress(&recorder);  // a line on stderr during a long run, on a terminal
    const CoverageOutcome outcome = run_coverage(scenario, &progress, trace.get());

    const FigureFile figure = opts->figures.file();
    const std::string ext(extension(figure.format));
    AtomicFile final_file(work / "final.json"), scene(work / ("scene." + ext)),
        cost(work / ("cost." + ext));
    AtomicFile scenario_copy(work / "scenario.json");
    scenario_copy.stream() << readable_json(portable_scenario(
                                  scenario, fs::path(opts->scenario.file).parent_path()))
                           << "\n";
    final_file.stream() << final_json(outcome);
    SceneOptions scene_options;
    scene_options.layers = opts->figures.drawn();
    if (!recorder.known_cells().empty()) scene_options.known = &recorder.known_cells();
    scene.stream() << scene_figure(scenario, outcome, recorder.tracks(), scene_options, figure);
    cost.stream() << cost_figure(recorder.samples(), outcome, false, figure);
    recorder.commit();
    scenario_copy.commit();
    final_file.commit();
    scene.commit();
    cost.commit();
    folder->commit();
    if (trace) trace->commit();

    std::size_t projected = 0;
    for (const RobotOutcome& r : outcome.robots)
      projected += r.projected ? 1 : 0;
    fmt::print("{} after {:.2f} s simulated ({} events): {} robots, {} projected\n",
               outcome.converged ? "converged" : "not converged (" + outcome.stop_reason + ")",
               outcome.sim_time.seconds(), outcome.events, outcome.robots.size(), projected);
    fmt::print("cost: virtual {:.6g}, real {:.6g}, real in virtual partition {:.6g}\n",
               outcome.cost_virtual, outcome.cost_real, outcome.cost_real_in_virtual_partition);
    fmt::print("fingerprint {}\n", Fingerprint::to_hex(outcome.fingerprint));
    // A result, not an error: the baseline without a planner fails as the paper says.
    if (const auto& l = outcome.left_environment)
      fmt::print(
          "robot {} left Ω at ({:.6g}, {:.6g}), t = {:.2f} s, on its way to ({:.6g}, {:.6g})\n",
          l->robot, l->position.x, l->position.y, l->time.seconds(), l->goal.x, l->goal.y);
    // After the folder and the summary: a failed encoding leaves the run's outputs whole, and no
    // video.
    const std::string& video = opts->figures.video;
    if (!video.empty()) {
      try {
        VideoOptions settings = opts->figures.video_settings();
        if (!recorder.known_cells().empty()) settings.known = &recorder.known_cells();
        write_run_video(scenario, outcome, recorder.tracks(), video, settings);
      } catch (const std::runtime_error& e) {
        throw InputError(fmt::format("--video: {}", e.what()));
      }
    }
    if (const auto& f = outcome.planner_failure) {
      // The results rest on the planner's promise; a broken promise fails the run.
      throw std::runtime_error(fmt::format(
          "planner failure: robot {} at t = {} s declared its goal ({}, {}), which lies in Ω, "
          "unreachable (it stood at ({}, {})); see {}/final.json",
          f->robot, f->time.seconds(), f->goal.x, f->goal.y, f->position.x, f->position.y,
          dir.string()));
    }
    fmt::print(
        "wrote {0}/scenario.json, {0}/final.json, {0}/{2}, {0}/metrics.csv, {0}/scene.{1}, "
        "{0}/cost.{1}{3}\n",
        dir.string(), ext, trajectory_file_name(recording.compress),
        video.empty() ? "" : ", " + video);
  });
}

}  // namespace covsim::app
