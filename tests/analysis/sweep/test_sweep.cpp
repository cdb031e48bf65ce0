#include <catch2/catch.hpp>

#include <unistd.h>

#include <fmt/format.h>
#include <filesystem>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>

#include "analysis/sweep/statistics.hpp"
#include "analysis/sweep/sweep_runner.hpp"
#include "scenarios/scenario_error.hpp"
#include "tests/analysis/sweep/sweep_files.hpp"

using namespace covsim;
namespace fs = std::filesystem;
using covsim::test::temp_dir;
using covsim::test::write_sweep;

namespace {
const std::string kSweep =
    R"({"scenario": ")" + std::string(COVSIM_SOURCE_DIR) + R"(/scenarios/two_obstacles.json",
  "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.4]},
  "seeds": [3, 4, 5]})";

// A CSV line's cells (none of summary.csv's cells here is quoted).
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');)
    out.push_back(cell);
  return out;
}

// Everything but the wall time.
std::vector<std::string> comparable(const std::vector<SweepResult>& rs) {
  std::vector<std::string> out;
  for (const auto& r : rs) {
    nlohmann::ordered_json v = r.values;
    v.erase("wall_time");
    v.erase("planner_step_time");
    out.push_back(fmt::format("{} {} {}", r.index, v.dump(), r.error.value_or("")));
  }
  return out;
}
}  // namespace

TEST_CASE("summary statistics by hand", "[sweep]") {
  const SampleSummary s = summarize_sample({2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0});
  CHECK(s.n == 8);
  CHECK(s.mean == Approx(5.0));
  CHECK(s.stddev == Approx(std::sqrt(32.0 / 7.0)));
  CHECK(s.ci95 == Approx(2.365 * std::sqrt(32.0 / 7.0) / std::sqrt(8.0)));
  CHECK(summarize_sample({3.0}).ci95 == 0.0);
  CHECK(student_t_975(1) == Approx(12.706));
  CHECK(student_t_975(100) == Approx(1.984).epsilon(1e-3));
  // Type-7 quartiles: h = q (n - 1), interpolated between the order statistics around h.
  CHECK(s.median == 4.5);
  CHECK(s.q1 == 4.0);
  CHECK(s.q3 == Approx(5.5));
  const SampleSummary odd = summarize_sample({9.0, 1.0, 3.0, 7.0, 5.0});
  CHECK(odd.median == 5.0);
  CHECK(odd.q1 == 3.0);
  CHECK(odd.q3 == 7.0);
  CHECK(summarize_sample({3.0}).median == 3.0);
}

TEST_CASE("two modes are told apart from one spread-out mode", "[sweep]") {
  // Sixteen runs that settle near 14 s and four near 57 s: the mean (22.6 s) lies in neither.
  std::vector<double> times;
  for (int k = 0; k < 16; ++k)
    times.push_back(13.5 + 0.1 * k);
  for (double t : {55.0, 57.0, 58.5, 63.2})
    times.push_back(t);
  const Modes m = split_modes(times);
  CHECK(m.bimodal);
  CHECK(m.low_fraction == 0.8);
  CHECK(m.low_median == Approx(14.25));
  CHECK(m.high_median == Approx(57.75));
  // Evenly spread values, one straggler, two stragglers (under 15%), values in fine steps
  // and too small a sample are one mode.
  std::vector<double> even;
  for (int k = 0; k < 20; ++k)
    even.push_back(k);
  CHECK_FALSE(split_modes(even).bimodal);
  std::vector<double> stragglers(times.begin(), times.begin() + 16);
  stragglers.push_back(90.0);
  CHECK_FALSE(split_modes(stragglers).bimodal);
  stragglers.push_back(91.0);
  CHECK_FALSE(split_modes(stragglers).bimodal);
  std::vector<double> steps;
  for (int k = 0; k < 20; ++k)
    steps.push_back(k < 10 ? 500.0 : 502.0);
  CHECK_FALSE(split_modes(steps).bimodal);
  CHECK_FALSE(split_modes({0.0, 1.0, 2.0, 10.0, 11.0, 12.0}).bimodal);
  // A gap no wider than 1.5 times a side's range is no separation.
  CHECK_FALSE(split_modes({0, 1, 2, 3, 4, 5, 14, 16, 18, 20}).bimodal);
  CHECK(split_modes({0, 1, 2, 3, 4, 5, 14, 15, 16, 17}).bimodal);
}

TEST_CASE("one distribution is seldom called two modes; two separate ones nearly always",
          "[sweep]") {
  // Samples of 20, as a study's 20 seeds: normal, uniform, exponential and lognormal
  // (σ = 1), 2000 of each from a fixed seed. And mixtures: 16 runs from N(15, 1) and 4 from
  // N(15 + 24, 3²), the other mode eight of its standard deviations away.
  std::mt19937_64 rng(20261125);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::exponential_distribution<double> exponential(1.0);
  const std::vector<std::function<double()>> draws = {
      [&] { return 50.0 + 10.0 * normal(rng); }, [&] { return 10.0 + 40.0 * uniform(rng); },
      [&] { return 10.0 + 20.0 * exponential(rng); }, [&] { return 10.0 * std::exp(normal(rng)); }};
  for (std::size_t d = 0; d < draws.size(); ++d) {
    int two = 0;
    for (int k = 0; k < 2000; ++k) {
      std::vector<double> xs;
      for (int i = 0; i < 20; ++i)
        xs.push_back(draws[d]());
      two += split_modes(xs).bimodal ? 1 : 0;
    }
    INFO("distribution " << d);
    CHECK(two < 20);  // under 1%
  }
  int found = 0;
  for (int k = 0; k < 1000; ++k) {
    std::vector<double> xs;
    for (int i = 0; i < 20; ++i)
      xs.push_back(i < 16 ? 15.0 + normal(rng) : 39.0 + 3.0 * normal(rng));
    found += split_modes(xs).bimodal ? 1 : 0;
  }
  CHECK(found > 900);
}

TEST_CASE("a sweep gives the same results whatever the number of jobs", "[sweep]") {
  const fs::path dir = temp_dir("jobs");
  const SweepSpec spec = load_sweep(write_sweep(dir, kSweep));
  CHECK(spec.runs().size() == 6);
  CHECK(spec.parameters == std::vector<std::string>{"network.loss.model", "network.loss.p"});
  const auto one = run_sweep(spec, dir / "one", SweepOptions{1, false, 0, 1});
  const auto two = run_sweep(spec, dir / "two", SweepOptions{2, false, 0, 1});
  CHECK(comparable(one) == comparable(two));
  for (const auto& r : one)
    CHECK_FALSE(r.error);
  // Loss changes the runs; without loss the seed does not matter.
  CHECK(one[0].fingerprint() == one[1].fingerprint());
  CHECK(one[3].fingerprint() != one[4].fingerprint());
}

TEST_CASE("a rerun skips finished runs and redoes missing ones", "[sweep]") {
  const fs::path dir = temp_dir("resume");
  const SweepSpec spec = load_sweep(write_sweep(dir, kSweep));
  const auto first = run_sweep(spec, dir / "out", SweepOptions{2, false, 0, 1});
  // Mark one result (a rerun must keep it as it is) and remove another (it must be redone).
  {
    std::ifstream in(dir / "out" / "runs" / "1.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["wall_time"] = 12345.0;
    std::ofstream(dir / "out" / "runs" / "1.json") << j.dump();
  }
  fs::remove(dir / "out" / "runs" / "4.json");
  const auto second = run_sweep(spec, dir / "out", SweepOptions{2, false, 0, 1});
  CHECK(second[1].number("wall_time") == 12345.0);
  CHECK(fs::exists(dir / "out" / "runs" / "4.json"));
  CHECK(comparable(first) == comparable(second));
}

TEST_CASE("a rerun keeps results written before a measure was added, and redoes damaged ones",
          "[sweep]") {
  const fs::path dir = temp_dir("older");
  const SweepSpec spec = load_sweep(write_sweep(dir, kSweep));
  run_sweep(spec, dir / "out", SweepOptions{1, false, 0, 1});
  const auto edit = [&](const char* file, const char* key) {
    std::ifstream in(dir / "out" / "runs" / file);
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(in);
    j.erase(key);
    j["wall_time"] = 12345.0;  // a rerun would write it anew
    std::ofstream(dir / "out" / "runs" / file) << j.dump();
  };
  edit("1.json", "gap_min");      // a measure added later: an older covsim's result
  edit("2.json", "fingerprint");  // a measure every result has: damaged
  const auto second = run_sweep(spec, dir / "out", SweepOptions{1, false, 0, 1});
  CHECK(second[1].number("wall_time") == 12345.0);
  CHECK(second[1].values.at("gap_min").is_null());
  CHECK(second[2].number("wall_time") != 12345.0);
  CHECK(second[2].values.contains("fingerprint"));
}

TEST_CASE("a run whose series cannot be written is not recorded, and a rerun redoes it",
          "[sweep]") {
  const fs::path dir = temp_dir("series-full");
  const SweepSpec spec = load_sweep(write_sweep(dir, kSweep));
  // Run 2's series cannot be put in place (its name is taken by a folder), as on a full disk.
  fs::create_directories(dir / "out" / "runs" / "2.metrics.csv");
  const auto first = run_sweep(spec, dir / "out", SweepOptions{1, false, 0, 1, true});
  REQUIRE(first[2].error);
  CHECK_THAT(*first[2].error, Catch::Contains("cannot write its metrics series"));
  CHECK_FALSE(fs::exists(dir / "out" / "runs" / "2.json"));
  CHECK(fs::exists(dir / "out" / "runs" / "1.json"));
  // Space freed: the rerun runs it, and only it (run 1's result is not written again).
  fs::remove(dir / "out" / "runs" / "2.metrics.csv");
  const auto written = fs::last_write_time(dir / "out" / "runs" / "1.json");
  const auto second = run_sweep(spec, dir / "out", SweepOptions{1, false, 0, 1, true});
  CHECK(fs::last_write_time(dir / "out" / "runs" / "1.json") == written);
  CHECK_FALSE(second[2].error);
  CHECK(fs::is_regular_file(dir / "out" / "runs" / "2.metrics.csv"));
  CHECK(fs::exists(dir / "out" / "runs" / "2.json"));
}

TEST_CASE("a failing run is recorded and the sweep goes on", "[sweep]") {
  const fs::path dir = temp_dir("failure");
  SweepSpec spec = load_sweep(write_sweep(
      dir,
      R"({"scenario": ")" + std::string(COVSIM_SOURCE_DIR) +
          R"(/scenarios/u_shape.json", "grid": {"robots.max_speed": [0.1, 0.2]}, "seeds": [1]})"));
  // A sweep file with this value is refused before anything runs; a sweep built by a program
  // is not validated, and its failing run is recorded.
  spec.settings[1][0] = -1;
  const auto results = run_sweep(spec, dir / "out", SweepOptions{1, false, 0, 1});
  REQUIRE(results.size() == 2);
  CHECK_FALSE(results[0].error);
  CHECK(results[0].converged());
  REQUIRE(results[1].error);
  CHECK_THAT(*results[1].error,
             Catch::Contains("$.robots.max_speed: expected a number > 0 m/s, found -1"));
  write_runs_csv(dir / "out" / "runs.csv", spec, results);
  write_summary_csv(dir / "out" / "summary.csv", spec, results);
  std::ifstream in(dir / "out" / "summary.csv");
  std::string header, row0, row1;
  std::getline(in, header);
  std::getline(in, row0);
  std::getline(in, row1);
  // One run, one failed, none distinct: no convergence rate and no statistics, rather than
  // zeros.
  CHECK_THAT(row1, Catch::StartsWith("1,-1,1,1,0,,"));
  CHECK(row1.find_first_not_of(",", std::string("1,-1,1,1,0,").size()) == std::string::npos);
}

TEST_CASE("shards split the runs without overlap", "[sweep]") {
  const fs::path dir = temp_dir("shards");
  const SweepSpec spec = load_sweep(write_sweep(dir, kSweep));
  const auto a = run_sweep(spec, dir / "a", SweepOptions{1, false, 0, 2});
  const auto b = run_sweep(spec, dir / "b", SweepOptions{1, false, 1, 2});
  CHECK(a.size() + b.size() == 6);
  for (const auto& r : a)
    CHECK(r.index % 2 == 0);
  for (const auto& r : b)
    CHECK(r.index % 2 == 1);
}

TEST_CASE("sweep files are validated", "[sweep]") {
  const fs::path dir = temp_dir("errors");
  const std::string scenario =
      R"("scenario": ")" + std::string(COVSIM_SOURCE_DIR) + R"(/scenarios/u_shape.json")";
  auto error = [&](const std::string& body, const std::string& fragment) {
    CHECK_THROWS_WITH(load_sweep(write_sweep(dir, body)), Catch::Contains(fragment));
  };
  error("{" + scenario + R"(, "seeds": [1], "colour": 1})", "$.colour: unknown key");
  error("{" + scenario + R"(, "grid": {"seed": [1, 2]}, "seeds": [1]})",
        "\"seed\" is set by \"seeds\"");
  error("{" + scenario + R"(, "zip": {"a.b": [1, 2], "c.d": [1]}, "seeds": [1]})",
        "expected 2 values");
  error("{" + scenario + R"(, "grid": {"a": []}, "seeds": [1]})",
        "$.grid.a: expected at least one value");
  error("{" + scenario + R"(, "seeds": {"count": 0}})", "$.seeds.count: expected a count");
  error("{" + scenario + "}", "missing required key \"seeds\"");
  // Sizes that cannot be honoured are refused when read, before the grid is built: 100^4
  // settings from a few kilobytes, or a million settings times two seeds.
  std::string hundred = "[";
  for (int v = 0; v < 100; ++v)
    hundred += (v != 0 ? ", " : "") + std::to_string(v * 0.001 + 0.1);
  hundred += "]";
  error("{" + scenario + R"(, "grid": {"sensor.range": )" + hundred +
            R"(, "loops.loop2_period": )" + hundred + R"(, "network.loss.p": )" + hundred +
            R"(, "network.broadcast_period": )" + hundred + R"(}, "seeds": [1]})",
        "$.grid.sensor.range: the grid would have more than 1000000 settings");
  error("{" + scenario + R"(, "grid": {"sensor.range": )" + hundred +
            R"(, "loops.loop2_period": )" + hundred + R"(, "network.loss.p": )" + hundred +
            R"(}, "seeds": {"count": 2}})",
        "$.seeds: 1000000 settings × 2 seeds is more than the 1000000 runs a sweep holds");
  error(R"({"scenario": 3, "seeds": [1]})", "$.scenario: expected a scenario file name");
  // Every setting's scenario is loaded before anything runs; the error names the value.
  error("{" + scenario +
            R"(, "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.1, 2]},
                 "seeds": [1]})",
        "$.grid.network.loss.p[1]: network.loss.p = 2 gives an invalid scenario: "
        "$.network.loss.p: expected a number >= 0 and <= 1, found 2");
  error("{" + scenario + R"(, "grid": {"sensor.rnage": [1, 2]}, "seeds": [1]})",
        "$.grid.sensor.rnage[0]: sensor.rnage = 1 gives an invalid scenario: $.sensor.rnage: "
        "unknown key");
  error("{" + scenario +
            R"(, "zip": {"loops.mode": ["periodic", "periodic"],
                         "loops.loop1_period": [1, -1]}, "seeds": [1]})",
        "$.zip.loops.loop1_period[1]: loops.loop1_period = -1");
  // Repeats would count one setting or seed twice.
  error("{" + scenario + R"(, "seeds": [1, 2, 1]})", "$.seeds[2]: seed 1 is listed twice");
  error("{" + scenario + R"(, "grid": {"sensor.range": [1, 2, 1]}, "seeds": [1]})",
        "$.grid.sensor.range[2]: 1 is listed twice");
  error("{" + scenario +
            R"(, "zip": {"sensor.range": [1, 2, 1], "metrics.period": [0.5, 1, 0.5]},
                 "seeds": [1]})",
        "$.zip: rows 0 and 2 are the same setting");
}

TEST_CASE("a YAML sweep reads and runs as its JSON twin, and its errors have places",
          "[sweep][yaml]") {
  const fs::path dir = temp_dir("yaml");
  const std::string source = COVSIM_SOURCE_DIR;
  const SweepSpec json = load_sweep(write_sweep(dir, R"({"scenario": ")" + source +
                                                         R"(/scenarios/u_shape.json",
      "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.0, 0.4]},
      "seeds": [3]})"));
  const auto yaml_file = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  const SweepSpec yaml = load_sweep(yaml_file("sweep.yaml", "scenario: " + source +
                                                                R"(/scenarios/u_shape.yaml
grid:  # the same grid
  network.loss.model: [bernoulli]
  network.loss.p:
    - 0.0
    - 0.4
seeds: [3]
)"));
  nlohmann::json a = to_json(json), b = to_json(yaml);
  a.erase("source");
  b.erase("source");
  CHECK(a.dump() == b.dump());
  CHECK(comparable(run_sweep(yaml, dir / "yaml-out", SweepOptions{2, false, 0, 1})) ==
        comparable(run_sweep(json, dir / "json-out", SweepOptions{2, false, 0, 1})));

  const auto error = [&](const std::string& text) {
    try {
      load_sweep(yaml_file("bad.yaml", text));
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    FAIL("accepted: " << text);
    return std::string();
  };
  const std::string named = "scenario: " + source + "/scenarios/u_shape.yaml\n";
  CHECK_THAT(error(named + "grid:\n  network.loss.model: [bernoulli]\n  network.loss.p: [0.1, 2]\n"
                           "seeds: [1]\n"),
             Catch::Contains("bad.yaml:4:25: $.grid.network.loss.p[1]: network.loss.p = 2 gives "
                             "an invalid scenario: $.network.loss.p: expected a number"));
  CHECK_THAT(error(named + "seeds: [1, 2]\nseeds: [3]\n"),
             Catch::Contains("bad.yaml:3:1: $: duplicate key \"seeds\""));
  CHECK_THAT(error(named + "seeds: {count: 0}\n"),
             Catch::Contains("bad.yaml:2:16: $.seeds.count: expected a count"));
  // An inline scenario's error is placed at the value in the sweep file.
  CHECK_THAT(error("scenario:\n  environment: {outer: [[0, 0], [1, 0], [1, 1]]}\n"
                   "  density: {type: uniform}\n  robots: {positions: [[0.9, 0.1]], colour: 2}\n"
                   "seeds: [1]\n"),
             Catch::Contains("bad.yaml:4:45: $.scenario: the scenario is invalid: ") &&
                 Catch::Contains("$.robots.colour: unknown key"));
  // A scenario file's error names that file and the place in it.
  yaml_file("scenario.yaml",
            "environment: {outer: [[0, 0], [1, 0], [1, 1]]}\n"
            "density: {type: uniform, value: -1}\n");
  CHECK_THAT(error("scenario: scenario.yaml\nseeds: [1]\n"),
             Catch::Contains("bad.yaml:1:11: $.scenario: the scenario is invalid: ") &&
                 Catch::Contains("scenario.yaml:2:33: $.density.value: expected a number > 0"));
}

TEST_CASE("shards plus merge equal the whole sweep", "[sweep]") {
  const fs::path dir = temp_dir("merge");
  const SweepSpec spec = load_sweep(write_sweep(dir, kSweep));
  const auto whole = run_sweep(spec, dir / "whole", SweepOptions{2, false, 0, 1});
  write_runs_csv(dir / "whole" / "runs.csv", spec, whole);
  write_summary_csv(dir / "whole" / "summary.csv", spec, whole);
  std::vector<fs::path> shards;
  for (std::size_t k = 0; k < 4; ++k) {
    shards.push_back(dir / fmt::format("shard{}", k));
    run_sweep(spec, shards.back(), SweepOptions{1, false, k, 4});
  }
  SweepSpec merged_spec;
  const auto merged = merge_sweeps(shards, dir / "merged", merged_spec);
  CHECK(comparable(merged) == comparable(whole));
  CHECK(merged_spec.parameters == spec.parameters);
  // The files agree but for wall times and planner step times.
  auto without_wall_time = [](const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> rows;
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    std::stringstream hs(line);
    for (std::string f; std::getline(hs, f, ',');)
      header.push_back(f);
    while (std::getline(in, line)) {
      std::stringstream ls(line);
      std::string kept;
      std::size_t c = 0;
      for (std::string f; std::getline(ls, f, ','); ++c) {
        if (c < header.size() &&
            (header[c].rfind("wall_time", 0) == 0 || header[c].rfind("planner_step_time", 0) == 0))
          continue;
        kept += f + ",";
      }
      rows.push_back(kept);
    }
    return rows;
  };
  CHECK(without_wall_time(dir / "merged" / "runs.csv") ==
        without_wall_time(dir / "whole" / "runs.csv"));
  CHECK(without_wall_time(dir / "merged" / "summary.csv") ==
        without_wall_time(dir / "whole" / "summary.csv"));
  // Missing shards, and folders of different sweeps, are refused.
  SweepSpec unused;
  CHECK_THROWS_WITH(merge_sweeps({shards[0], shards[1]}, dir / "partial", unused),
                    Catch::Contains("in none of the folders"));
  const SweepSpec other =
      load_sweep(write_sweep(dir, R"({"scenario": ")" + std::string(COVSIM_SOURCE_DIR) +
                                      R"(/scenarios/fig2c.json", "seeds": [1]})"));
  run_sweep(other, dir / "other", SweepOptions{1, false, 0, 1});
  CHECK_THROWS_WITH(merge_sweeps({shards[0], dir / "other"}, dir / "mixed", unused),
                    Catch::Contains("different sweep"));
  CHECK_THROWS_WITH(run_sweep(other, shards[0], SweepOptions{1, false, 0, 1}),
                    Catch::Contains("different sweep"));
  // Shards whose sweep.json was edited so that a setting has fewer values than parameters:
  // refused as bad input naming the file, not read past the list's end.
  std::vector<fs::path> edited;
  for (std::size_t k = 0; k < 2; ++k) {
    edited.push_back(dir / fmt::format("edited{}", k));
    fs::create_directories(edited.back());
    nlohmann::json j = nlohmann::json::parse(std::ifstream(shards[k] / "sweep.json"));
    j["settings"][0].erase(j["settings"][0].size() - 1);
    std::ofstream(edited.back() / "sweep.json") << j.dump();
  }
  CHECK_THROWS_AS(merge_sweeps(edited, dir / "edited-out", unused), ScenarioError);
  CHECK_THROWS_WITH(merge_sweeps(edited, dir / "edited-out", unused),
                    Catch::Contains("edited0/sweep.json: not a sweep covsim wrote: setting 0 has"));
}

TEST_CASE("runs record their communication, and seeds deploy robots apart", "[sweep]") {
  const fs::path dir = temp_dir("communication");
  const std::string u = std::string(COVSIM_SOURCE_DIR) + "/scenarios/u_shape.json";
  // The ideal network and a lossy one; robots drawn per seed.
  const SweepSpec spec = load_sweep(write_sweep(dir, R"({"scenario": ")" + u + R"(",
      "grid": {"robots": [{"count": 5, "start": {"cluster": {"center": [0.15, 0.85], "radius": 0.12}}}],
               "network": [null, {"loss": {"model": "bernoulli", "p": 0.3}, "range": 0.4}]},
      "seeds": [1, 2]})"));
  const auto results = run_sweep(spec, dir / "out", SweepOptions{2, false, 0, 1, true});
  REQUIRE(results.size() == 4);
  for (const SweepResult& r : results)
    REQUIRE_FALSE(r.error);
  // Ideal: no messages, no stale information, no disagreement, always connected.
  for (const SweepResult* r : {&results[0], &results[1]}) {
    CHECK(r->number("messages_delivered") == 0);
    CHECK(r->number("info_age_mean") == 0);
    CHECK(r->number("area_claimed_by_several") == 0);
    CHECK(r->number("connected_fraction") == 1);
  }
  // Lossy and short-ranged: messages go astray, information ages, cells disagree.
  for (const SweepResult* r : {&results[2], &results[3]}) {
    CHECK(r->number("messages_delivered") > 0);
    CHECK(r->number("messages_lost") > 0);
    CHECK(r->number("info_age_mean") > 0);
    CHECK(r->number("info_age_max") >= r->number("info_age_mean"));
    CHECK(r->number("area_claimed_by_several") + r->number("area_claimed_by_none") > 0);
    CHECK(r->number("connected_fraction") >= 0);
    CHECK(r->number("connected_fraction") <= 1);
  }
  // Two seeds, two deployments: different runs even with the ideal network.
  CHECK(results[0].fingerprint() != results[1].fingerprint());
  // --keep-series kept every run's samples, and a merge brings them along.
  for (std::size_t i = 0; i < 4; ++i)
    CHECK(fs::exists(dir / "out" / "runs" / fmt::format("{}.metrics.csv", i)));
  SweepSpec merged;
  merge_sweeps({dir / "out"}, dir / "merged", merged);
  CHECK(fs::exists(dir / "merged" / "runs" / "3.metrics.csv"));
}

TEST_CASE("a measure no run took is left empty in summary.csv, never nan", "[sweep]") {
  // λ2 switched off for every robot count: each run's algebraic_connectivity_min is null
  // while its graph stays connected (u_shape's robots all within range).
  const fs::path dir = temp_dir("untaken");
  const std::string u = std::string(COVSIM_SOURCE_DIR) + "/scenarios/u_shape.json";
  const SweepSpec spec = load_sweep(write_sweep(dir, R"({"scenario": ")" + u + R"(",
      "grid": {"network": [{"range": 5.0}], "metrics.algebraic_connectivity_robots": [0, 10]},
      "seeds": [1, 2]})"));
  const auto results = run_sweep(spec, dir / "out", SweepOptions{2, false, 0, 1, false});
  REQUIRE(results.size() == 4);
  for (const SweepResult& r : results) {
    REQUIRE_FALSE(r.error);
    CHECK(std::isnan(r.number("algebraic_connectivity_min")) == (r.index < 2));
  }
  write_summary_csv(dir / "out" / "summary.csv", spec, results);
  std::ifstream in(dir / "out" / "summary.csv");
  std::string header, off, on;
  std::getline(in, header);
  std::getline(in, off);
  std::getline(in, on);
  CHECK_THAT(off + on, !Catch::Contains("nan"));
  // The column's mean, sd and interval: empty without λ2, numbers with it.
  const std::vector<std::string> names = cells(header), a = cells(off), b = cells(on);
  const auto at = std::find(names.begin(), names.end(), "algebraic_connectivity_min_mean");
  REQUIRE(at != names.end());
  const auto k = static_cast<std::size_t>(at - names.begin());
  REQUIRE(a.size() > k);
  REQUIRE(b.size() > k);
  CHECK(a[k].empty());
  CHECK(std::stod(b[k]) > 0);
}

TEST_CASE("seeds that give one run are counted once, and said", "[sweep]") {
  // Two settings of three seeds: in the first, seeds 1 and 3 ran the same run (one
  // fingerprint), in the second every seed differs.
  const fs::path dir = temp_dir("identical_seeds");
  const std::string u = std::string(COVSIM_SOURCE_DIR) + "/scenarios/u_shape.json";
  const SweepSpec spec = load_sweep(write_sweep(dir, R"({"scenario": ")" + u + R"(",
      "grid": {"robots.max_speed": [0.1, 0.2]}, "seeds": [1, 2, 3]})"));
  const auto result = [](std::size_t index, const char* fingerprint, double time) {
    SweepResult r;
    r.index = index;
    r.values["converged"] = true;
    r.values["sim_time"] = time;
    r.values["fingerprint"] = fingerprint;
    return r;
  };
  const std::vector<SweepResult> results{
      result(0, "00000000000000aa", 10.0), result(1, "00000000000000bb", 20.0),
      result(2, "00000000000000aa", 10.0), result(3, "00000000000000c1", 1.0),
      result(4, "00000000000000c2", 2.0),  result(5, "00000000000000c3", 3.0)};
  write_summary_csv(dir / "summary.csv", spec, results);
  std::ifstream in(dir / "summary.csv");
  std::string header, first, second;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, second);
  const std::vector<std::string> names = cells(header), a = cells(first), b = cells(second);
  const auto column = [&](const std::vector<std::string>& row, const std::string& name) {
    const auto at = std::find(names.begin(), names.end(), name);
    REQUIRE(at != names.end());
    return row.at(static_cast<std::size_t>(at - names.begin()));
  };
  CHECK(column(a, "runs") == "3");
  CHECK(column(a, "distinct_runs") == "2");
  CHECK(column(b, "distinct_runs") == "3");
  // The mean of 10 and 20, not of 10, 20 and 10; a spread from two runs.
  CHECK(std::stod(column(a, "sim_time_mean")) == 15.0);
  CHECK(std::stod(column(a, "sim_time_std")) == Approx(std::sqrt(50.0)));
  CHECK(std::stod(column(b, "sim_time_mean")) == 2.0);

  const std::vector<std::string> warnings = identical_seed_warnings(spec, results);
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::StartsWith("setting 0, robots.max_speed=0.1: 2 distinct runs of 3 "
                                            "(seed 3 = seed 1: the same fingerprint)"));
  CHECK_THAT(warnings[0], Catch::Contains("robots.jitter"));
  // Past the lines shown, how many more.
  std::vector<SweepResult> all_same;
  for (std::size_t i = 0; i < 6; ++i)
    all_same.push_back(result(i, i < 3 ? "00000000000000aa" : "00000000000000bb", 1.0));
  const std::vector<std::string> capped = identical_seed_warnings(spec, all_same, 1);
  REQUIRE(capped.size() == 2);
  CHECK_THAT(capped[1], Catch::StartsWith("1 more settings with identical runs"));
  // Every seed's run its own: nothing to say.
  CHECK(identical_seed_warnings(spec, {results[3], results[4], results[5]}).empty());
}
