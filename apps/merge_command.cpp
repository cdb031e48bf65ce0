// `covsim merge DIR... --out DIR`: combines the folders of a sweep's shards into the
// runs.csv, summary.csv and plots a single run of the whole sweep gives. With one folder and
// --out the same folder it redraws the plots (--format, --group) from the runs kept there.
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "analysis/figures/sweep_charts.hpp"
#include "analysis/sweep/sweep_folder.hpp"
#include "analysis/sweep/sweep_runner.hpp"
#include "analysis/sweep/sweep_tables.hpp"
#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/output_guard.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim::app {

void add_merge_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> dirs;
    std::string out;
    std::string group;
    std::string format = "svg";
    std::vector<std::string> measures;
  };
  auto opts = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("merge", "Combine the output folders of a sweep's shards");
  cmd->add_option("DIR", opts->dirs, "Output folders of covsim sweep --shard")->required();
  cmd->add_option("--out", opts->out, "Folder for the combined results")->required();
  cmd->add_option("--group", opts->group, "Plot one line per value of this swept parameter");
  cmd->add_option("--measures", opts->measures,
                  "Draw charts of these measures only (comma-separated summary.csv measures)")
      ->delimiter(',');
  cmd->add_option("--format", opts->format, "Plots as svg, pdf or png")
      ->check(CLI::IsMember({"svg", "pdf", "png"}))
      ->capture_default_str();
  cmd->callback([opts] {
    std::vector<std::filesystem::path> dirs(opts->dirs.begin(), opts->dirs.end());
    const auto lock = guard_output(opts->out);  // one writer at a time
    SweepSpec spec;
    std::vector<SweepResult> results;
    try {
      // --group is checked before anything is written.
      if (!dirs.empty()) check_chart_group(sweep_of_folder(dirs.front()), opts->group);
      check_chart_measures(opts->measures);
      results = merge_sweeps(dirs, opts->out, spec);
    } catch (const ScenarioError&) {
      throw;                             // names the file and what was expected
    } catch (const std::exception& e) {  // runtime_error, or invalid_argument for --group
      throw InputError(e.what());
    }
    write_sweep_plots(opts->out, spec, results, opts->group, *parse_figure_format(opts->format),
                      opts->measures);
    // A warning lost to a full or closed stderr is not the sweep's failure.
    for (const std::string& line : identical_seed_warnings(spec, results))
      std::fprintf(stderr, "covsim: warning: %s\n", line.c_str());
    fmt::print("merged {} runs from {} folders into {}/runs.csv and {}/summary.csv\n",
               results.size(), dirs.size(), opts->out, opts->out);
  });
}

}  // namespace covsim::app
