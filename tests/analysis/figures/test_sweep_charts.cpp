// A sweep's charts (analysis/figures/sweep_charts): which plots a sweep gives and their lines.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "analysis/figures/sweep_charts.hpp"
#include "analysis/sweep/setting_words.hpp"
#include "analysis/sweep/sweep_runner.hpp"
#include "analysis/sweep/sweep_tables.hpp"
#include "tests/analysis/sweep/sweep_files.hpp"

using namespace covsim;
namespace fs = std::filesystem;
using covsim::test::temp_dir;
using covsim::test::write_sweep;

TEST_CASE("plots group their lines by a chosen parameter", "[sweep]") {
  const fs::path dir = temp_dir("group");
  const SweepSpec spec =
      load_sweep(write_sweep(dir, R"({"scenario": ")" + std::string(COVSIM_SOURCE_DIR) +
                                      R"(/scenarios/two_obstacles.json",
      "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.4],
               "network.broadcast_period": [0.1, 0.5]}, "seeds": [1, 2]})"));
  const auto results = run_sweep(spec, dir / "out", SweepOptions{2, false, 0, 1});
  const auto grouped = write_sweep_plots(dir / "out", spec, results, "network.broadcast_period");
  // Plots against p only (the grouping parameter is never an x axis), one line per period.
  CHECK_FALSE(grouped.empty());
  for (const fs::path& f : grouped)
    CHECK_THAT(f.filename().string(), Catch::EndsWith("_vs_network.loss.p.svg"));
  const auto charts = sweep_charts(spec, results, "network.broadcast_period");
  REQUIRE(charts.size() == grouped.size());
  for (const SweepChart& c : charts) {
    REQUIRE(c.chart.series.size() == 2);
    CHECK(c.chart.series[0].label == "network.broadcast_period = 0.1 s");
    CHECK(c.chart.series[1].label == "network.broadcast_period = 0.5 s");
    CHECK(c.chart.series[0].samples.size() == 4);  // 2 values of p x 2 seeds, as dots
  }
  // Without a group, plots exist against both parameters.
  const auto all = write_sweep_plots(dir / "out", spec, results);
  CHECK(all.size() == 2 * grouped.size());
  CHECK_THROWS_WITH(write_sweep_plots(dir / "out", spec, results, "planner.type"),
                    Catch::Contains("not a swept parameter"));
}

TEST_CASE("an unlimited (null) value is left off a plot's axis, not the plot", "[sweep]") {
  const fs::path dir = temp_dir("null-axis");
  const SweepSpec spec =
      load_sweep(write_sweep(dir, R"({"scenario": ")" + std::string(COVSIM_SOURCE_DIR) +
                                      R"(/scenarios/u_shape.json",
      "grid": {"sensor.range": [0.1, 0.5, null]}, "seeds": [1]})"));
  const auto results = run_sweep(spec, dir / "out", SweepOptions{2, false, 0, 1});
  REQUIRE(results.size() == 3);
  const auto plots = write_sweep_plots(dir / "out", spec, results, "");
  REQUIRE_FALSE(plots.empty());
  for (const fs::path& f : plots)
    CHECK_THAT(f.filename().string(), Catch::EndsWith("_vs_sensor.range.svg"));
  // The runs.csv still holds the unlimited run.
  write_runs_csv(dir / "out" / "runs.csv", spec, results);
  std::ifstream in(dir / "out" / "runs.csv");
  const std::string csv((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(csv, Catch::Contains(",null,"));
}

TEST_CASE("a measure the same in every run gets no chart; index.html shows the sweep", "[sweep]") {
  // Message loss on u_shape: the radio's, the bodies' and the mapping's measures are 0 or
  // not taken in every run; they drew 8 of 35 charts of nothing.
  const fs::path dir = temp_dir("applies");
  const SweepSpec spec =
      load_sweep(write_sweep(dir, R"({"scenario": ")" + std::string(COVSIM_SOURCE_DIR) +
                                      R"(/scenarios/u_shape.json",
      "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.3, 0.6]},
      "seeds": [1, 2]})"));
  const auto results = run_sweep(spec, dir / "out", SweepOptions{2, false, 0, 1});
  const auto charts = sweep_charts(spec, results);
  REQUIRE_FALSE(charts.empty());
  for (const SweepChart& c : charts) {
    INFO(c.name);
    const std::string metric = c.name.substr(0, c.name.find("_vs_"));
    std::set<double> values;
    for (const SweepResult& r : results)
      if (!std::isnan(r.number(metric))) values.insert(r.number(metric));
    CHECK(values.size() > 1);
  }
  for (const char* idle : {"turn_time", "contact_time", "map_bytes", "deadlocks", "phy_drops"}) {
    INFO(idle);
    CHECK(std::none_of(charts.begin(), charts.end(),
                       [&](const SweepChart& c) { return c.name.rfind(idle, 0) == 0; }));
  }
  // The page: the settings, the summary table, every chart.
  write_summary_csv(dir / "out" / "summary.csv", spec, results);
  const auto files = write_sweep_plots(dir / "out", spec, results);
  std::ifstream in(dir / "out" / "index.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(html, Catch::Contains("<table id=\"settings\">") &&
                       Catch::Contains("<table id=\"summary\">") &&
                       Catch::Contains("<td>0.6</td>"));
  for (const fs::path& f : files)
    CHECK_THAT(html, Catch::Contains("<img src=\"" + f.filename().string() + "\""));
}

TEST_CASE("a swept value as words", "[sweep_charts]") {
  CHECK(setting_words("planner.type", "grid_astar") == "grid_astar");
  CHECK(setting_words("sensor.range", nullptr) == "unlimited");
  CHECK(setting_words("sensor.range", 0.5) == "0.5 m");
  CHECK(setting_words("network.loss.p", 0.3) == "0.3");
  CHECK(setting_words("loops", {{"mode", "periodic"}, {"loop1_period", 0.1}}) ==
        "periodic, loop1_period 0.1 s");
  CHECK(setting_words("loops", {{"mode", "classic"}}) == "classic");
}

TEST_CASE("a categorical parameter gets a chart of its categories", "[sweep]") {
  // Planners and whole loop schedules: "0 plots" before; now a chart by each, its values as
  // categories in words, one set of points per value of the other.
  const fs::path dir = temp_dir("categories");
  const SweepSpec spec =
      load_sweep(write_sweep(dir, R"({"scenario": ")" + std::string(COVSIM_SOURCE_DIR) +
                                      R"(/scenarios/u_shape.json",
      "grid": {"robots.jitter": [0.05], "planner.type": ["tangent_bug", "grid_astar"],
               "loops": [{"mode": "classic"}, {"mode": "periodic", "loop1_period": 0.5}]},
      "seeds": [1, 2]})"));
  const auto results = run_sweep(spec, dir / "out", SweepOptions{2, false, 0, 1});
  const auto charts = sweep_charts(spec, results);
  const auto named = [&](const std::string& name) {
    const auto c = std::find_if(charts.begin(), charts.end(),
                                [&](const SweepChart& s) { return s.name == name; });
    REQUIRE(c != charts.end());
    return c->chart;
  };
  const LineChart planners = named("sim_time_by_planner.type");
  CHECK(planners.x_categories == std::vector<std::string>{"tangent_bug", "grid_astar"});
  CHECK(planners.x_label == "planner.type");
  REQUIRE(planners.series.size() == 2);
  CHECK(planners.series[0].label == "loops = classic");
  CHECK(planners.series[1].label == "loops = periodic, loop1_period 0.5 s");
  for (const ChartSeries& s : planners.series) {
    REQUIRE(s.points.size() == 2);  // one per planner, at x = 0 and 1
    CHECK(s.points[0].x == 0.0);
    CHECK(s.points[1].x == 1.0);
    CHECK(s.samples.size() == 4);  // 2 planners x 2 seeds
  }
  // Facets: a panel per schedule, its series alone, on one y range; drawn one above the
  // other (twice a chart's height).
  const auto facets = std::find_if(charts.begin(), charts.end(), [](const SweepChart& c) {
                        return c.name == "sim_time_by_planner.type";
                      })->panels;
  REQUIRE(facets.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    REQUIRE(facets[k].series.size() == 1);
    CHECK(facets[k].series[0].label == planners.series[k].label);
    CHECK(facets[k].x_categories == planners.x_categories);
    CHECK(facets[k].y_cover_lo == facets[0].y_cover_lo);
    CHECK(facets[k].y_cover_hi == facets[0].y_cover_hi);
  }
  CHECK(facets[1].title == "sim_time: loops = periodic, loop1_period 0.5 s");
  const auto height = [](const std::string& svg) {
    const auto at = svg.find("height=\"") + 8;
    return std::stod(svg.substr(at, svg.find('"', at) - at));
  };
  CHECK(height(draw_chart_panels(facets, FigureFile{FigureFormat::svg, 0})) ==
        Approx(2 * height(draw_line_chart(planners, FigureFile{FigureFormat::svg, 0}))));
  const LineChart loops = named("sim_time_by_loops");
  CHECK(loops.x_categories == std::vector<std::string>{"classic", "periodic, loop1_period 0.5 s"});
  // The one-valued jitter draws nothing; every chart is drawn.
  CHECK(std::none_of(charts.begin(), charts.end(), [](const SweepChart& c) {
    return c.name.find("robots.jitter") != std::string::npos;
  }));
  const auto files = write_sweep_plots(dir / "out", spec, results);
  CHECK(files.size() == charts.size());
  CHECK(fs::file_size(dir / "out" / "sim_time_by_loops.svg") > 1000);
}

TEST_CASE("a log-spaced axis is drawn on a log scale; --measures chooses the charts", "[sweep]") {
  const fs::path dir = temp_dir("log-axis");
  const auto charts_over = [&](const std::string& values, std::vector<std::string> measures) {
    const SweepSpec spec =
        load_sweep(write_sweep(dir, R"({"scenario": ")" + std::string(COVSIM_SOURCE_DIR) +
                                        R"(/scenarios/u_shape.json", "grid": {"sensor.range": )" +
                                        values + R"(}, "seeds": [1]})"));
    std::vector<SweepResult> results;
    for (std::size_t i = 0; i < spec.runs().size(); ++i) {
      SweepResult r;
      r.index = i;
      r.values["sim_time"] = 10.0 + static_cast<double>(i);
      r.values["path_length"] = 1.0 + static_cast<double>(i);
      r.values["wall_time"] = 0.1 * static_cast<double>(i + 1);
      results.push_back(r);
    }
    return sweep_charts(spec, results, "", std::move(measures));
  };
  for (const auto& [values, log] :
       std::vector<std::pair<std::string, bool>>{{"[0.01, 0.1, 1, 10]", true},
                                                 {"[0.1, 0.2, 0.5, 1, 2, 5]", true},
                                                 {"[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]", false},
                                                 {"[0.5, 2]", false}}) {
    INFO(values);
    const auto charts = charts_over(values, {});
    REQUIRE(charts.size() == 2);  // sim_time and path_length; not the wall time
    for (const SweepChart& c : charts)
      CHECK(c.chart.log_x == log);
  }
  const auto chosen = charts_over("[0.5, 2]", {"wall_time"});
  REQUIRE(chosen.size() == 1);
  CHECK(chosen[0].name == "wall_time_vs_sensor.range");
  CHECK_THROWS_WITH(charts_over("[0.5, 2]", {"cost_reel"}),
                    Catch::Contains("\"cost_reel\" is not a measure") &&
                        Catch::Contains("did you mean 'cost_real'"));
}
