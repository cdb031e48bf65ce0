// `covsim chart bars TABLE.csv --group COL --series COL --value COL --out FILE`: the mean of
// a column per (group, series) as a grouped bar chart, drawn like every other figure (SVG,
// PDF or PNG by FILE's extension), and the means as CSV on standard output. Scripts that tabulate
// runs (compare-planners) plot this way rather than drawing their own.
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "analysis/bar_chart.hpp"
#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "core/atomic_file.hpp"

namespace covsim::app {

namespace {
// One CSV record: fields separated by commas, a field in double quotes may hold commas and
// doubled quotes.
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        out.back() += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      out.emplace_back();
    } else if (ch != '\r') {
      out.back() += ch;
    }
  }
  return out;
}
}  // namespace

void add_chart_command(CLI::App& app) {
  struct Options {
    std::string table, group, series, value, title, y_label, out;
  };
  auto o = std::make_shared<Options>();
  CLI::App* chart = app.add_subcommand("chart", "Draw a chart of a CSV table");
  chart->require_subcommand(1);
  CLI::App* cmd = chart->add_subcommand(
      "bars", "Grouped bars: the mean of --value per --group and --series (empty, nan skipped)");
  cmd->add_option("TABLE", o->table, "CSV file with a header row")->required();
  cmd->add_option("--group", o->group, "Column whose values are the groups along x")->required();
  cmd->add_option("--series", o->series, "Column whose values are the bars in a group")->required();
  cmd->add_option("--value", o->value, "Numeric column averaged per bar")->required();
  cmd->add_option("--title", o->title, "Title");
  cmd->add_option("--y-label", o->y_label, "The y axis' label, with its unit");
  cmd->add_option("--out", o->out, "Figure file: .svg, .pdf or .png")->required();
  cmd->callback([o] {
    const std::filesystem::path out = o->out;
    const auto format = parse_figure_format(
        out.extension().string().substr(std::min<std::size_t>(1, out.extension().string().size())));
    if (!format)
      throw InputError(fmt::format("--out: {}: expected a .svg, .pdf or .png file", o->out));
    std::ifstream in(o->table);
    if (!in) throw InputError(fmt::format("{}: cannot read", o->table));
    std::string line;
    if (!std::getline(in, line)) throw InputError(fmt::format("{}: empty, no header", o->table));
    const std::vector<std::string> header = csv_fields(line);
    const auto column = [&](const std::string& name, const char* option) {
      const auto it = std::find(header.begin(), header.end(), name);
      if (it == header.end())
        throw InputError(
            fmt::format("{}: {}: no column \"{}\" in {}", option, o->table, name, line));
      return static_cast<std::size_t>(it - header.begin());
    };
    const std::size_t g = column(o->group, "--group"), s = column(o->series, "--series"),
                      v = column(o->value, "--value");
    BarChart chart{o->title, o->y_label.empty() ? o->value : o->y_label, {}, {}, {}};
    std::map<std::pair<std::size_t, std::size_t>, std::pair<double, std::size_t>> sums;
    const auto index = [](std::vector<std::string>& names, const std::string& n) {
      const auto it = std::find(names.begin(), names.end(), n);
      if (it != names.end()) return static_cast<std::size_t>(it - names.begin());
      names.push_back(n);
      return names.size() - 1;
    };
    for (std::size_t row = 2; std::getline(in, line); ++row) {
      if (line.empty()) continue;
      const std::vector<std::string> f = csv_fields(line);
      if (f.size() != header.size())
        throw InputError(fmt::format("{}:{}: {} fields, the header has {}", o->table, row, f.size(),
                                     header.size()));
      const std::string& text = f[v];
      if (text.empty() || text == "nan") continue;
      double x = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
      if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(x))
        throw InputError(fmt::format("{}:{}: column \"{}\": expected a number, found \"{}\"",
                                     o->table, row, o->value, text));
      auto& [sum, n] = sums[{index(chart.groups, f[g]), index(chart.series, f[s])}];
      sum += x;
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
          fmt::print("\"{}\",\"{}\",{},{}\n", chart.groups[gi], chart.series[si],
                     chart.values[gi][si].value(), it->second.second);
    AtomicFile file(out);
    file.stream() << draw_bar_chart(chart, FigureFile{*format, 0});
    file.commit();
  });
}

}  // namespace covsim::app
