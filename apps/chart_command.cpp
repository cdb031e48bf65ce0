// `covsim chart bars|lines TABLE.csv ...`: a CSV table drawn like every other figure (SVG, PDF
// or PNG by --out's extension), with the numbers drawn as CSV on standard output. Scripts that
// tabulate runs (compare-planners) plot this way rather than drawing their own.
//   bars: the mean of --value per (--group, --series) as grouped bars.
//   lines: a line of (--x, --y) points per --series value, on linear or log axes.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/figures/bar_chart.hpp"
#include "analysis/figures/line_chart.hpp"
#include "apps/commands.hpp"
#include "apps/csv_table.hpp"
#include "apps/input_error.hpp"
#include "io/atomic_file.hpp"

namespace covsim::app {

namespace {
FigureFormat out_format(const std::filesystem::path& out) {
  const std::string ext = out.extension().string();
  const auto format = parse_figure_format(ext.substr(std::min<std::size_t>(1, ext.size())));
  if (!format)
    throw InputError(fmt::format("--out: {}: expected a .svg, .pdf or .png file", out.string()));
  return *format;
}

void write_figure(const std::filesystem::path& out, const std::string& figure) {
  AtomicFile file(out);
  file.stream() << figure;
  file.commit();
}

// The index of `name` in `names`, appended if new: groups and series in order of appearance.
std::size_t index_of(std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return static_cast<std::size_t>(it - names.begin());
  names.push_back(name);
  return names.size() - 1;
}

// What every chart takes: the table, a title and the figure file.
struct ChartFiles {
  std::string table, title, out;
  void add_to(CLI::App* cmd) {
    cmd->add_option("TABLE", table, "CSV file with a header row")->required();
    cmd->add_option("--title", title, "Title");
    cmd->add_option("--out", out, "Figure file: .svg, .pdf or .png")->required();
  }
};

void add_bars(CLI::App* chart) {
  struct Options : ChartFiles {
    std::string group, series, value, y_label;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = chart->add_subcommand(
      "bars", "Grouped bars: the mean of --value per --group and --series (empty, nan skipped)");
  o->add_to(cmd);
  cmd->add_option("--group", o->group, "Column whose values are the groups along x")->required();
  cmd->add_option("--series", o->series, "Column whose values are the bars in a group")->required();
  cmd->add_option("--value", o->value, "Numeric column averaged per bar")->required();
  cmd->add_option("--y-label", o->y_label, "The y axis' label, with its unit");
  cmd->callback([o] {
    const FigureFormat format = out_format(o->out);
    const CsvTable t = CsvTable::read(o->table);
    const std::size_t g = t.column(o->group, "--group"), s = t.column(o->series, "--series"),
                      v = t.column(o->value, "--value");
    BarChart chart{o->title, o->y_label.empty() ? o->value : o->y_label, {}, {}, {}};
    std::map<std::pair<std::size_t, std::size_t>, std::pair<double, std::size_t>> sums;
    for (const CsvRow& row : t.rows) {
      const std::optional<double> x = t.number(row, v);
      if (!x) continue;
      auto& [sum, n] =
          sums[{index_of(chart.groups, row.fields[g]), index_of(chart.series, row.fields[s])}];
      sum += *x;
      ++n;
    }
    chart.values.assign(chart.groups.size(),
                        std::vector<std::optional<double>>(chart.series.size()));
    for (const auto& [key, sn] : sums)
      chart.values[key.first][key.second] = sn.first / static_cast<double>(sn.second);
    // The numbers drawn, as CSV on standard output.
    fmt::print("{},{},mean,count\n", o->group, o->series);
    for (std::size_t gi = 0; gi < chart.groups.size(); ++gi)
      for (std::size_t si = 0; si < chart.series.size(); ++si)
        if (const auto it = sums.find({gi, si}); it != sums.end())
          fmt::print("{},{},{},{}\n", csv_quoted(chart.groups[gi]), csv_quoted(chart.series[si]),
                     chart.values[gi][si].value(), it->second.second);
    write_figure(o->out, draw_bar_chart(chart, FigureFile{format, 0}));
  });
}

void add_lines(CLI::App* chart) {
  struct Options : ChartFiles {
    std::string x, y, series, x_label, y_label;
    bool log_x = false, log_y = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = chart->add_subcommand(
      "lines", "Lines: --y against --x, one line per --series value (empty, nan skipped)");
  o->add_to(cmd);
  cmd->add_option("--x", o->x, "Numeric column along x")->required();
  cmd->add_option("--y", o->y, "Numeric column along y")->required();
  cmd->add_option("--series", o->series, "Column whose values are the lines (default: one line)");
  cmd->add_flag("--log-x", o->log_x, "x on a base-10 log scale (values must be > 0)");
  cmd->add_flag("--log-y", o->log_y, "y on a base-10 log scale (values must be > 0)");
  cmd->add_option("--x-label", o->x_label, "The x axis' label, with its unit (default: --x)");
  cmd->add_option("--y-label", o->y_label, "The y axis' label, with its unit (default: --y)");
  cmd->callback([o] {
    const FigureFormat format = out_format(o->out);
    const CsvTable t = CsvTable::read(o->table);
    const std::size_t xc = t.column(o->x, "--x"), yc = t.column(o->y, "--y");
    const bool by_series = !o->series.empty();
    const std::size_t sc = by_series ? t.column(o->series, "--series") : 0;
    // A log axis has no place for zero or below: say which row has one.
    const auto positive = [&](const CsvRow& row, std::size_t column, double v, const char* flag) {
      if (!(v > 0))
        throw InputError(fmt::format("{}:{}: column \"{}\": {} needs values above 0, found {}",
                                     t.file, row.line, t.header[column], flag, v));
    };
    std::vector<std::string> labels;
    std::vector<std::vector<ChartPoint>> points;
    for (const CsvRow& row : t.rows) {
      const std::optional<double> x = t.number(row, xc), y = t.number(row, yc);
      if (!x || !y) continue;
      if (o->log_x) positive(row, xc, *x, "--log-x");
      if (o->log_y) positive(row, yc, *y, "--log-y");
      const std::size_t k = index_of(labels, by_series ? row.fields[sc] : std::string());
      points.resize(labels.size());
      points[k].push_back({*x, *y});
    }
    LineChart chart;
    chart.title = o->title;
    chart.x_label = o->x_label.empty() ? o->x : o->x_label;
    chart.y_label = o->y_label.empty() ? o->y : o->y_label;
    chart.log_x = o->log_x;
    chart.log_y = o->log_y;
    // The points drawn, in the order drawn, as CSV on standard output.
    fmt::print("{},{},{}\n", o->series.empty() ? "series" : o->series, o->x, o->y);
    for (std::size_t k = 0; k < labels.size(); ++k) {
      std::stable_sort(points[k].begin(), points[k].end(),
                       [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x; });
      for (const ChartPoint& p : points[k])
        fmt::print("{},{},{}\n", csv_quoted(labels[k]), p.x, p.y);
      chart.series.push_back({labels[k], std::move(points[k]), false, false, {}});
    }
    write_figure(o->out, draw_line_chart(chart, FigureFile{format, 0}));
  });
}
}  // namespace

void add_chart_command(CLI::App& app) {
  CLI::App* chart = app.add_subcommand("chart", "Draw a chart of a CSV table");
  chart->require_subcommand(1);
  add_bars(chart);
  add_lines(chart);
}

}  // namespace covsim::app
