// The result records are described once (analysis/records/result_fields.cpp); the writers follow
// the tables, and the documentation lists the same fields in the same order.
#include <catch2/catch.hpp>

#include <algorithm>

#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>
#include <sstream>

#include "analysis/records/final_json.hpp"
#include "analysis/records/result_fields.hpp"
#include "analysis/sweep/sweep_runner.hpp"

using namespace covsim;

namespace {
std::string doc(const std::string& name) {
  std::ifstream in(std::string(COVSIM_SOURCE_DIR) + "/docs/" + name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

template <class R>
std::vector<std::string> names(const FieldTable<R>& t) {
  std::vector<std::string> out;
  for (const auto& f : t)
    out.push_back(f.name);
  return out;
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

// Dotted keys of a JSON object, in document order, nested objects flattened except those
// named in `leaves` (fields whose value is a JSON object).
void flatten(const nlohmann::ordered_json& j, const std::string& prefix,
             std::vector<std::string>& out,
             const std::vector<std::string>& leaves = {"provenance"}) {
  for (const auto& [k, v] : j.items()) {
    if (v.is_object() && std::find(leaves.begin(), leaves.end(), prefix + k) == leaves.end()) {
      flatten(v, prefix + k + ".", out, leaves);
    } else {
      out.push_back(prefix + k);
    }
  }
}
}  // namespace

TEST_CASE("docs/outputs.md lists final.json's fields in the table's order", "[fields]") {
  const std::string text = doc("outputs.md");
  const auto at = text.find("```json\n", text.find("## final.json"));
  REQUIRE(at != std::string::npos);
  const auto end = text.find("```", at + 8);
  const auto example = nlohmann::ordered_json::parse(text.substr(at + 8, end - at - 8));
  std::vector<std::string> documented;
  flatten(example, "", documented);
  CHECK(documented == names(final_fields()));
  std::vector<std::string> robot;
  flatten(example["robots"][0], "", robot);
  CHECK(robot == names(robot_fields()));
  // What the writer writes has the same keys.
  CoverageOutcome o;
  o.robots.resize(2);
  std::vector<std::string> written;
  flatten(nlohmann::ordered_json::parse(final_json(o)), "", written);
  CHECK(written == names(final_fields()));
}

TEST_CASE("docs/outputs.md gives metrics.csv's header from the table", "[fields]") {
  const std::string text = doc("outputs.md");
  const std::smatch m = [&] {
    std::smatch r;
    std::regex_search(text, r, std::regex("Header `(t,cost_real[^`]*)`"));
    return r;
  }();
  REQUIRE(m.size() == 2);
  CHECK(m[1].str() == csv_header(metrics_fields()));
}

TEST_CASE("docs/sweeps.md lists runs.csv's columns and summary.csv's metrics from the table",
          "[fields]") {
  const std::string text = doc("sweeps.md");
  std::smatch m;
  REQUIRE(std::regex_search(text, m,
                            std::regex("`run,setting,<parameters\\.\\.\\.>,seed,([^`]*),error`")));
  CHECK(split(m[1].str(), ",") == names(run_fields()));
  REQUIRE(std::regex_search(text, m, std::regex("then for each of\\s*`([^`]*)`:")));
  CHECK(split(m[1].str(), ", ") == sweep_metrics());
}

TEST_CASE("every field has a description, and units where it has a dimension", "[fields]") {
  const auto check = [](const auto& table) {
    for (const auto& f : table) {
      INFO(f.name);
      CHECK_FALSE(f.description.empty());
      CHECK(static_cast<bool>(f.get));
      const bool timed = f.name.find("time") != std::string::npos;
      if (timed && f.kind == FieldKind::number) CHECK_FALSE(f.unit.empty());
    }
  };
  check(final_fields());
  check(robot_fields());
  check(metrics_fields());
  check(run_fields());
}
