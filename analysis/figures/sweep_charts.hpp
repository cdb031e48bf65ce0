#pragma once
// A sweep's charts: one per (measure, varying swept parameter) for each measure that takes
// more than one value over the sweep's runs. A numeric parameter gives
// "<measure>_vs_<parameter>": the mean with a 95% confidence band and the runs as dots; any
// other (a planner, a loss model, a loop schedule) gives "<measure>_by_<parameter>", its
// values as categories named in words (analysis/sweep/setting_words), the runs as dots and
// the mean with its 95% interval at each, one panel (facet) per combination of the others.
// One line (or panel) per value of `group` (a swept parameter; the others pooled), or
// without one, per combination of the other varying parameters.
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
  // A categorical chart with other varying parameters: one panel per combination of them
  // (facets, drawn one above the other), each with that combination's series alone.
  std::vector<LineChart> panels;
};
// Throws std::invalid_argument ("--group: ... is not a swept parameter") unless `group` is
// empty or a swept parameter of `spec`.
void check_chart_group(const SweepSpec& spec, const std::string& group);
// Throws std::invalid_argument ("--measures: ... is not a measure ...", with the nearest
// names) unless every name is a measure summary.csv summarises.
void check_chart_measures(const std::vector<std::string>& measures);
// Throws std::invalid_argument for a group that is not swept or a measure that is not one.
// `measures`: the measures to draw (empty: every one that differs over the runs, but the
// wall time). A numeric axis whose values are log-spaced is drawn on a log scale.
std::vector<SweepChart> sweep_charts(const SweepSpec& spec, const std::vector<SweepResult>& results,
                                     const std::string& group = "",
                                     const std::vector<std::string>& measures = {});
// The charts drawn as DIR/<name>.svg (or .pdf, .png), and DIR/index.html showing the sweep
// and all of them (analysis/figures/sweep_index). Returns the charts written.
std::vector<std::filesystem::path> write_sweep_plots(const std::filesystem::path& dir,
                                                     const SweepSpec& spec,
                                                     const std::vector<SweepResult>& results,
                                                     const std::string& group = "",
                                                     FigureFormat format = FigureFormat::svg,
                                                     const std::vector<std::string>& measures = {});

}  // namespace covsim
