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
    CHECK(c.chart.series[0].label == "network.broadcast_period = 0.1");
    CHECK(c.chart.series[1].label == "network.broadcast_period = 0.5");
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
