#pragma once
// A sweep's charts: one per (measure, numeric swept parameter) for each measure that takes
// more than one value over the sweep's runs, named
// "<measure>_vs_<parameter>": the mean with a 95% confidence band and the runs as dots, one
// line per value of `group` (a swept parameter; the others pooled), or without one, per
// combination of the other varying parameters.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/figures/canvas.hpp"
#include "analysis/figures/line_chart.hpp"
#include "analysis/sweep/sweep_result.hpp"
#include "analysis/sweep/sweep_spec.hpp"

namespace covsim {

struct SweepChart {
  std::string name;
  LineChart chart;
};
// Throws std::invalid_argument ("--group: ... is not a swept parameter") unless `group` is
// empty or a swept parameter of `spec`.
void check_chart_group(const SweepSpec& spec, const std::string& group);
// Throws std::invalid_argument for a group that is not swept.
std::vector<SweepChart> sweep_charts(const SweepSpec& spec, const std::vector<SweepResult>& results,
                                     const std::string& group = "");
// The charts drawn as DIR/<name>.svg (or .pdf, .png), and DIR/index.html showing the sweep
// and all of them (analysis/figures/sweep_index). Returns the charts written.
std::vector<std::filesystem::path> write_sweep_plots(const std::filesystem::path& dir,
                                                     const SweepSpec& spec,
                                                     const std::vector<SweepResult>& results,
                                                     const std::string& group = "",
                                                     FigureFormat format = FigureFormat::svg);

}  // namespace covsim
