// A sweep's records follow the table of measures (analysis/records/measure.cpp): runs.csv and
// runs/<i>.json have a column for each measure a sweep records, in its place, summary.csv
// the statistics of each summarised one, and docs/sweeps.md lists the same.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "analysis/records/result_fields.hpp"
#include "analysis/sweep/sweep_runner.hpp"
#include "analysis/sweep/sweep_tables.hpp"
#include "tests/doc_text.hpp"

using namespace covsim;
namespace fs = std::filesystem;

namespace {
std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> split(const std::string& s, const std::string& by) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t at = s.find(by); at != std::string::npos;
       start = at + by.size(), at = s.find(by, start))
    out.push_back(s.substr(start, at - start));
  out.push_back(s.substr(start));
  return out;
}

// The runs.csv columns of the measures, in their places, read from the table itself.
std::vector<std::string> measure_columns() {
  std::vector<std::string> out;
  for (int place = 0;; ++place) {
    const auto m = std::find_if(measures().begin(), measures().end(),
                                [&](const Measure& x) { return x.run_place == place; });
    if (m == measures().end()) return out;
    out.push_back(m->column());
  }
}

std::vector<std::string> summarized_columns() {
  std::vector<std::string> out;
  for (const std::string& c : measure_columns()) {
    const auto m = std::find_if(measures().begin(), measures().end(),
                                [&](const Measure& x) { return x.run_place && x.column() == c; });
    if (m->summarized) out.push_back(c);
  }
  return out;
}
}  // namespace

TEST_CASE("a sweep's files have a column for every measure it records", "[fields]") {
  const fs::path dir =
      fs::temp_directory_path() / ("covsim-sweep-fields-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "sweep.json")
      << R"({"scenario": ")" << COVSIM_SOURCE_DIR << R"(/scenarios/u_shape.json",
    "grid": {"network.loss.model": ["bernoulli"], "network.loss.p": [0.2]}, "seeds": [1]})";
  const SweepSpec spec = load_sweep(dir / "sweep.json");
  const auto results = run_sweep(spec, dir / "out", SweepOptions{1, false, 0, 1});
  write_runs_csv(dir / "out" / "runs.csv", spec, results);
  write_summary_csv(dir / "out" / "summary.csv", spec, results);

  const std::vector<std::string> columns = measure_columns();
  REQUIRE(columns.size() == run_fields().size());  // no place left out or taken twice
  std::vector<std::string> runs = {"run", "setting", "network.loss.model", "network.loss.p",
                                   "seed"};
  runs.insert(runs.end(), columns.begin(), columns.end());
  runs.push_back("error");
  const std::vector<std::string> lines = split(read_text(dir / "out" / "runs.csv"), "\n");
  CHECK(split(lines.at(0), ",") == runs);
  CHECK(split(lines.at(1), ",").size() == runs.size());

  const auto result = nlohmann::ordered_json::parse(read_text(result_file(dir / "out", 0)));
  std::vector<std::string> keys;
  for (const auto& [k, v] : result.items())
    keys.push_back(k);
  keys.erase(keys.begin());  // "index"
  CHECK(keys == columns);

  const std::string summary = split(read_text(dir / "out" / "summary.csv"), "\n").at(0);
  CHECK(sweep_metrics() == summarized_columns());
  for (const std::string& c : summarized_columns()) {
    INFO(c);
    CHECK(summary.find("," + c + "_mean,") != std::string::npos);
  }

  // Beside each table, its columns in CSVW metadata: the header's names in order, with the
  // measures' units, the swept parameters' and the statistics' (a spread in the measure's).
  for (const char* table : {"runs.csv", "summary.csv"}) {
    INFO(table);
    const auto meta =
        nlohmann::json::parse(read_text(dir / "out" / (std::string(table) + "-metadata.json")));
    CHECK(meta["@context"] == "http://www.w3.org/ns/csvw");
    CHECK(meta["url"] == table);
    std::vector<std::string> names;
    std::map<std::string, std::string> unit;
    for (const auto& c : meta["tableSchema"]["columns"]) {
      names.push_back(c["name"].get<std::string>());
      if (c.contains("schema:unitText")) unit[names.back()] = c["schema:unitText"];
    }
    CHECK(names == split(split(read_text(dir / "out" / table), "\n").at(0), ","));
    CHECK(unit["sim_time"] == (std::string(table) == "runs.csv" ? "s" : ""));
    CHECK(unit.count("network.loss.p") == 0);  // a probability has no unit
  }
  const auto summary_meta =
      nlohmann::json::parse(read_text(dir / "out" / "summary.csv-metadata.json"));
  std::map<std::string, std::string> unit;
  for (const auto& c : summary_meta["tableSchema"]["columns"])
    unit[c["name"]] = c.value("schema:unitText", "");
  CHECK(unit["sim_time_mean"] == "s");
  CHECK(unit["sim_time_std"] == "s");
  CHECK(unit["sim_time_modes"].empty());
  CHECK(unit["path_length_q3"] == "m");
  // A swept parameter with a unit keeps it.
  SweepSpec ranged = spec;
  ranged.parameters = {"sensor.range"};
  CHECK(runs_columns(ranged).at(2).unit == "m");
  fs::remove_all(dir);
}

TEST_CASE("docs/sweeps.md lists runs.csv's columns and summary.csv's metrics from the table",
          "[fields]") {
  const std::string text = read_text(fs::path(COVSIM_SOURCE_DIR) / "docs" / "sweeps.md");
  const std::string head = "run,setting,<parameters...>,seed,", tail = ",error";
  const auto columns = test::code_span_starting(text, head);
  REQUIRE(columns);
  REQUIRE(columns->size() > head.size() + tail.size());
  REQUIRE(columns->ends_with(tail));
  CHECK(split(columns->substr(head.size(), columns->size() - head.size() - tail.size()), ",") ==
        measure_columns());
  const auto summarized = test::code_span_after(text, "then for each of");
  REQUIRE(summarized);
  CHECK(split(*summarized, ", ") == summarized_columns());
}
