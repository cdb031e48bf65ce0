#include "analysis/figures/sweep_charts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "analysis/figures/sweep_index.hpp"
#include "analysis/records/result_fields.hpp"
#include "analysis/sweep/setting_words.hpp"
#include "analysis/sweep/statistics.hpp"
#include "analysis/sweep/sweep_tables.hpp"
#include "core/spelling.hpp"
#include "io/atomic_file.hpp"
#include "scenarios/scenario_description.hpp"

namespace covsim {

namespace fs = std::filesystem;

namespace {
// Whether a measure takes more than one value over the sweep's runs: one that is the same
// (or not taken) in every run (a radio's measure without a radio, a count that stays 0)
// gets no chart.
bool differs(const std::vector<SweepResult>& results, const std::string& metric) {
  std::optional<double> first;
  for (const SweepResult& r : results) {
    if (r.error) continue;
    const double y = r.number(metric);
    if (std::isnan(y)) continue;
    if (!first)
      first = y;
    else if (y != *first)
      return true;
  }
  return false;
}

// Whether positive values are spaced evenly on a log scale rather than a linear one (0.01,
// 0.1, 1; or 0.1, 0.2, 0.5, 1, 2, 5): at least three, spanning a decade or more, their
// steps more even in log than in linear terms.
bool log_spaced(const std::set<double>& values) {
  if (values.size() < 3 || !(*values.begin() > 0.0) || *values.rbegin() < 10.0 * *values.begin())
    return false;
  const auto spread = [&](auto&& f) {  // coefficient of variation of the steps
    std::vector<double> steps;
    for (auto a = values.begin(), b = std::next(a); b != values.end(); ++a, ++b)
      steps.push_back(f(*b) - f(*a));
    const SampleSummary s = summarize_sample(steps);
    return s.stddev / s.mean;
  };
  return spread([](double v) { return std::log(v); }) < spread([](double v) { return v; });
}

std::string run_field_unit(const std::string& name) {
  for (const auto& f : run_fields()) {
    if (f.name == name) return f.unit;
  }
  return "";
}
}  // namespace

void check_chart_measures(const std::vector<std::string>& measures) {
  const std::vector<std::string> known = sweep_metrics();
  for (const std::string& m : measures) {
    if (std::find(known.begin(), known.end(), m) != known.end()) continue;
    const std::vector<std::string> near = closest_spellings(m, known);
    std::string hint;
    for (std::size_t k = 0; k < near.size(); ++k)
      hint += fmt::format("{}'{}'", k == 0 ? "; did you mean " : " or ", near[k]);
    throw std::invalid_argument(fmt::format(
        "--measures: \"{}\" is not a measure summary.csv summarises{} (docs/sweeps.md)", m, hint));
  }
}

void check_chart_group(const SweepSpec& spec, const std::string& group) {
  if (!group.empty() &&
      std::find(spec.parameters.begin(), spec.parameters.end(), group) == spec.parameters.end())
    throw std::invalid_argument("--group: \"" + group + "\" is not a swept parameter");
}

std::vector<SweepChart> sweep_charts(const SweepSpec& spec, const std::vector<SweepResult>& results,
                                     const std::string& group,
                                     const std::vector<std::string>& measures) {
  check_chart_group(spec, group);
  check_chart_measures(measures);
  std::optional<std::size_t> group_index;
  for (std::size_t q = 0; q < spec.parameters.size(); ++q) {
    if (spec.parameters[q] == group) group_index = q;
  }
  std::vector<SweepChart> charts;
  const std::vector<SweepRun> runs = spec.runs();
  // Parameters that take more than one value: only these name the lines.
  std::vector<bool> varies(spec.parameters.size(), false);
  for (std::size_t q = 0; q < spec.parameters.size(); ++q) {
    for (const auto& s : spec.settings)
      varies[q] = varies[q] || s[q] != spec.settings.front()[q];
  }
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    if (!varies[p] || (group_index && *group_index == p)) continue;
    // Numbers (and null, an unlimited value, left off the axis) with at least two values make
    // an x axis; any other parameter (a planner, a loop schedule) makes categories, in the
    // order the settings first take them.
    bool numeric = true;
    std::set<double> values;
    std::vector<nlohmann::json> categories;
    for (const auto& s : spec.settings) {
      numeric = numeric && (s[p].is_number() || s[p].is_null());
      if (numeric && s[p].is_number()) values.insert(s[p].get<double>());
      if (std::find(categories.begin(), categories.end(), s[p]) == categories.end())
        categories.push_back(s[p]);
    }
    const bool categorical = !numeric;
    if (numeric && values.size() < 2) continue;
    const auto x_of = [&](const nlohmann::json& v) {
      return categorical ? static_cast<double>(std::find(categories.begin(), categories.end(), v) -
                                               categories.begin())
                         : v.get<double>();
    };
    for (const std::string& metric : sweep_metrics()) {
      const bool chosen = std::find(measures.begin(), measures.end(), metric) != measures.end();
      // Chosen measures are drawn (wall time too); by default the ones that differ.
      // (The wall time varies by machine, the loop ratio is the setting's own: no chart.)
      if (measures.empty()
              ? metric == "wall_time" || metric == "loop_ratio" || !differs(results, metric)
              : !chosen)
        continue;
      // One line per value of the grouping parameter (pooling the others), or else per
      // combination of the other varying parameters; points at this parameter's values.
      std::map<std::string, std::map<double, std::vector<double>>> lines;
      for (const SweepResult& r : results) {
        const SweepRun& run = runs.at(r.index);
        if (r.error || (!categorical && run.values[p].is_null())) continue;
        const double y = r.number(metric);
        if (std::isnan(y)) continue;  // not taken by that run
        std::string label;
        for (std::size_t q = 0; q < spec.parameters.size(); ++q) {
          const bool names_line = group_index ? q == *group_index : varies[q];
          if (q != p && names_line)
            label += (label.empty() ? "" : ", ") + spec.parameters[q] + " = " +
                     setting_words(spec.parameters[q], run.values[q]);
        }
        lines[label.empty() ? "mean over seeds" : label][x_of(run.values[p])].push_back(y);
      }
      std::vector<ChartSeries> series;
      for (const auto& [label, points] : lines) {
        ChartSeries s{label, {}, true, false, {}};
        for (const auto& [x, ys] : points) {
          const SampleSummary sum = summarize_sample(ys);
          s.points.push_back({x, sum.mean, sum.mean - sum.ci95, sum.mean + sum.ci95});
          for (double y : ys)
            s.samples.emplace_back(x, y);
        }
        series.push_back(std::move(s));
      }
      // A metric no run took (a simulated radio's count with the abstract channel): no chart.
      if (series.empty()) continue;
      const auto with_unit = [](const std::string& name, const std::string& unit) {
        return unit.empty() ? name : fmt::format("{} [{}]", name, unit);
      };
      LineChart chart;
      chart.title = fmt::format("{} (mean, 95% confidence {}; dots: runs)", metric,
                                categorical ? "interval" : "band");
      chart.y_label = with_unit(metric, run_field_unit(metric));
      chart.series = std::move(series);
      std::vector<LineChart> panels;
      if (categorical) {
        chart.x_label = spec.parameters[p];
        for (const auto& v : categories)
          chart.x_categories.push_back(setting_words(spec.parameters[p], v));
        // Facets: a panel per combination of the other parameters, on one y range.
        double lo = INFINITY, hi = -INFINITY;
        for (const ChartSeries& s : chart.series) {
          for (const ChartPoint& q : s.points)
            lo = std::min({lo, q.lo, q.y}), hi = std::max({hi, q.hi, q.y});
          for (const auto& [x, y] : s.samples)
            lo = std::min(lo, y), hi = std::max(hi, y);
        }
        if (chart.series.size() > 1)
          for (const ChartSeries& s : chart.series) {
            LineChart panel = chart;
            panel.y_cover_lo = lo;
            panel.y_cover_hi = hi;
            panel.title = fmt::format("{}: {}", metric, s.label);
            panel.series = {s};
            panels.push_back(std::move(panel));
          }
      } else {
        chart.x_label = with_unit(spec.parameters[p], scenario_key_unit(spec.parameters[p]));
        chart.log_x = log_spaced(values);
      }
      charts.push_back(
          {fmt::format("{}_{}_{}", metric, categorical ? "by" : "vs", spec.parameters[p]),
           std::move(chart), std::move(panels)});
    }
  }
  return charts;
}

std::vector<fs::path> write_sweep_plots(const fs::path& dir, const SweepSpec& spec,
                                        const std::vector<SweepResult>& results,
                                        const std::string& group, FigureFormat format,
                                        const std::vector<std::string>& measures) {
  std::vector<fs::path> written;
  for (const SweepChart& c : sweep_charts(spec, results, group, measures)) {
    const fs::path file = dir / fmt::format("{}.{}", c.name, extension(format));
    AtomicFile f(file);
    f.stream() << (c.panels.empty() ? draw_line_chart(c.chart, FigureFile{format, 0})
                                    : draw_chart_panels(c.panels, FigureFile{format, 0}));
    f.commit();
    written.push_back(file);
  }
  write_sweep_index(dir, spec, results, written);
  return written;
}

}  // namespace covsim
