// `covsim sweep SWEEP --out DIR --jobs N [--shard K/N]`: every (setting, seed) of a sweep
// file as an independent run; writes DIR/runs.csv, DIR/summary.csv and plots (SVG, PDF or PNG).
// Reruns skip runs whose results exist. Exit code 1 if any run failed (each failure is recorded).
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>

#include "analysis/figures/sweep_charts.hpp"
#include "analysis/sweep/sweep_runner.hpp"
#include "analysis/sweep/sweep_tables.hpp"
#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/output_guard.hpp"
#include "apps/plugin_loader.hpp"

namespace covsim::app {

void add_sweep_command(CLI::App& app) {
  struct Options {
    std::string sweep;
    std::string out;
    std::size_t jobs = std::max(1u, std::thread::hardware_concurrency());
    std::string shard = "0/1";
    std::string group;
    std::string format = "svg";
    std::vector<std::string> measures;
    bool keep_series = false;
    std::vector<std::string> plugins;
  };
  auto opts = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("sweep", "Run a parameter sweep over seeds");
  cmd->add_option("SWEEP", opts->sweep, "Sweep file")->required();
  cmd->add_option("--out", opts->out, "Output directory")->required();
  cmd->add_option("--jobs", opts->jobs, "Runs at once (threads)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  cmd->add_option("--group", opts->group, "Plot one line per value of this swept parameter");
  cmd->add_option("--measures", opts->measures,
                  "Draw charts of these measures only (comma-separated summary.csv measures; "
                  "default: every one that differs over the runs)")
      ->delimiter(',');
  cmd->add_option("--format", opts->format, "Plots as svg, pdf or png")
      ->check(CLI::IsMember({"svg", "pdf", "png"}))
      ->capture_default_str();
  cmd->add_flag("--keep-series", opts->keep_series,
                "Keep each run's metrics (metrics.csv's columns) as DIR/runs/<index>.metrics.csv");
  add_plugin_option(cmd, opts->plugins);
  cmd->add_option("--shard", opts->shard, "Run only slice K of N (K in 0..N-1), for clusters")
      ->capture_default_str();
  cmd->callback([opts] {
    load_plugins(opts->plugins);
    std::size_t k = 0, n = 1;
    if (std::sscanf(opts->shard.c_str(), "%zu/%zu", &k, &n) != 2 || n == 0 || k >= n ||
        opts->shard != fmt::format("{}/{}", k, n)) {
      throw InputError(
          fmt::format("--shard: expected K/N with 0 <= K < N, found \"{}\"", opts->shard));
    }
    const SweepSpec spec = load_sweep(opts->sweep);
    try {
      check_chart_group(spec, opts->group);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("{} of {}", e.what(), opts->sweep));
    }
    try {
      check_chart_measures(opts->measures);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
    const std::filesystem::path dir = opts->out;
    // One writer at a time (a second process resuming the same folder is refused).
    const auto lock = guard_output(dir);
    const std::vector<SweepResult> results =
        run_sweep(spec, dir, SweepOptions{opts->jobs, true, k, n, opts->keep_series});
    write_runs_csv(dir / "runs.csv", spec, results);
    write_summary_csv(dir / "summary.csv", spec, results);
    const auto plots = write_sweep_plots(dir, spec, results, opts->group,
                                         *parse_figure_format(opts->format), opts->measures);
    // A warning lost to a full or closed stderr is not the sweep's failure.
    for (const std::string& line : identical_seed_warnings(spec, results))
      std::fprintf(stderr, "covsim: warning: %s\n", line.c_str());
    std::size_t failed = 0, converged = 0;
    for (const SweepResult& r : results) {
      failed += r.error ? 1 : 0;
      converged += (!r.error && r.converged()) ? 1 : 0;
    }
    fmt::print("{} runs ({} settings x {} seeds{}): {} converged, {} failed\n", results.size(),
               spec.settings.size(), spec.seeds.size(),
               n > 1 ? fmt::format(", shard {}/{}", k, n) : "", converged, failed);
    fmt::print("wrote {0}/runs.csv, {0}/summary.csv, {1} plots and {0}/index.html\n", dir.string(),
               plots.size());
    if (failed > 0)
      throw std::runtime_error(
          fmt::format("{} runs failed; their errors are in {}/runs.csv", failed, dir.string()));
  });
}

}  // namespace covsim::app
