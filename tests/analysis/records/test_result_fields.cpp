// The measures are declared once (analysis/records/measure.cpp) and final.json's and a sweep's
// fields derived from them; the writers follow the tables, and docs/outputs.md lists the same
// fields in the same order.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "analysis/records/final_json.hpp"
#include "analysis/records/result_fields.hpp"
#include "analysis/records/run_recorder.hpp"
#include "tests/doc_text.hpp"

using namespace covsim;
using ojson = nlohmann::ordered_json;

namespace {
template <class R>
std::vector<std::string> names(const FieldTable<R>& t) {
  std::vector<std::string> out;
  for (const auto& f : t)
    out.push_back(f.name);
  return out;
}

// Dotted keys of a JSON object, in document order, nested objects flattened except those
// named in `leaves` (fields whose value is a JSON object).
void flatten(const ojson& j, const std::string& prefix, std::vector<std::string>& out,
             const std::vector<std::string>& leaves = {"provenance"}) {
  for (const auto& [k, v] : j.items()) {
    if (v.is_object() && std::find(leaves.begin(), leaves.end(), prefix + k) == leaves.end()) {
      flatten(v, prefix + k + ".", out, leaves);
    } else {
      out.push_back(prefix + k);
    }
  }
}

// A run whose every measure holds a value of its own, none a default.
RunMeasures known_run() {
  RunMeasures m;
  CoverageOutcome& o = m.outcome;
  o.scenario = "scenarios/known.json";
  o.converged = true;
  o.sim_time = SimTime::from_seconds(12.5);
  RobotOutcome r;
  r.position = {1.5, 2.5};
  r.virtual_generator = {1.75, 2.75};
  r.virtual_target = {-3.0, 0.5};
  r.real_target = {0.25, 0.5};
  r.projected = true;
  r.status = PlanStatus::stalled;
  r.path_length = 6.5;
  r.target_outside_steps = 17;
  r.stalled_time = 1.25;
  r.centroid_distance = 0.375;
  o.robots = {r};
  o.cost_virtual = 0.11;
  o.cost_real = 0.12;
  o.cost_real_in_virtual_partition = 0.13;
  o.fingerprint = 0x0123456789abcdefULL;
  o.decentralized = true;
  o.network = NetworkTotals{21, 22, 23, 24, 0.5, 0.75, RadioTotals{31, 32, 33, 0.25}};
  o.time_to_10_percent = 3.25;
  o.time_to_5_percent = 4.25;
  o.time_to_1_percent = 5.25;
  o.cost_to_best = 1.0625;
  o.path_length = 9.5;
  o.target_outside_steps = 31;
  o.stalled_time = 0.75;
  o.centroid_distance_mean = 0.0125;
  o.centroid_distance_max = 0.025;
  o.radius = 0.0375;
  o.body_gap_min = -0.005;
  o.contact_time = 1.5;
  o.wall_contacts = 3;
  o.deadlocks = 4;
  o.deadlock_time = 2.25;
  o.deadlocks_resolved = 3;
  o.turn_time = 6.5;
  o.hard_stops = 2;
  o.localization_error_mean = 0.003;
  o.localization_error_max = 0.0125;
  o.fixes = 640;
  o.known = "none";
  o.known_fraction = 0.875;
  o.known_fraction_min = 0.75;
  o.mapping_time_90 = 10.5;
  o.mapping_time_100 = NAN;
  o.map_disagreement = 0.0625;
  o.map_bytes = 4096;
  o.map_bytes_new = 1024;
  o.scans = 55;
  o.obstacles = 3;
  o.obstacles_known_min = 2;
  o.discoveries = 5;
  o.cost_known = 0.096;
  o.map_model = "occupancy";
  o.map_false_occupied = 0.0025;
  o.map_false_free = 0.015625;
  o.loop_ratio = 10.0;
  o.planner_steps = 200;
  o.planner_seconds = 0.0005;  // 2.5 µs a step
  o.stop_reason = "planner_failure";
  o.planner_failure = RobotIncident{3, SimTime::from_seconds(7.0), {1.0, 2.0}, {3.0, 4.0}};
  o.left_environment = RobotIncident{2, SimTime::from_seconds(8.0), {5.0, 6.0}, {7.0, 8.0}};
  o.events = 4321;
  o.seed = 77;
  o.provenance = {{"version", "9.9.9"}};
  m.communication = CommunicationSummary{0.5, 1.5, 0.25, 0.125, 0.875, NAN};
  m.wall_time = 3.5;
  return m;
}

// known_run() as final.json holds it, written out by hand.
const ojson kKnownFinal = ojson::parse(R"({
  "scenario": "scenarios/known.json", "converged": true, "sim_time": 12.5,
  "robots": [{"position": [1.5, 2.5], "virtual_generator": [1.75, 2.75],
              "virtual_target": [-3.0, 0.5], "real_target": [0.25, 0.5], "projected": true,
              "status": "stalled", "path_length": 6.5, "target_outside_steps": 17,
              "stalled_time": 1.25, "centroid_distance": 0.375}],
  "cost": {"virtual": 0.11, "real": 0.12, "real_in_virtual_partition": 0.13},
  "fingerprint": "0123456789abcdef",
  "network": {"decentralized": true, "messages_sent": 21, "messages_delivered": 22,
              "messages_lost": 23, "messages_unreachable": 24,
              "delivery_ratio": 1.0476190476190477, "latency_mean": 0.5, "latency_p95": 0.75,
              "channel_occupancy": 0.25, "phy_drops": 32, "transmissions": 31,
              "mac_drops": 33},
  "convergence": {"time_to_10_percent": 3.25, "time_to_5_percent": 4.25,
                  "time_to_1_percent": 5.25, "cost_to_best": 1.0625, "path_length": 9.5},
  "failures": {"target_outside_steps": 31, "stalled_time": 0.75,
               "centroid_distance_mean": 0.0125, "centroid_distance_max": 0.025},
  "bodies": {"radius": 0.0375, "gap_min": -0.005, "contact_time": 1.5, "wall_contacts": 3,
             "deadlocks": 4, "deadlock_time": 2.25, "deadlocks_resolved": 3,
             "turn_time": 6.5, "hard_stops": 2},
  "localization": {"error_mean": 0.003, "error_max": 0.0125, "fixes": 640},
  "mapping": {"known": "none", "known_fraction": 0.875, "known_fraction_min": 0.75,
              "time_to_90_percent": 10.5, "time_to_100_percent": null,
              "disagreement": 0.0625, "bytes": 4096, "bytes_new": 1024, "scans": 55, "obstacles": 3,
              "obstacles_known_min": 2, "discoveries": 5, "model": "occupancy",
              "false_occupied": 0.0025, "false_free": 0.015625, "cost_known": 0.096,
              "cost_ratio": 1.25},
  "loops": {"ratio": 10.0},
  "planner": {"steps": 200, "step_time_us": 2.5},
  "stop_reason": "planner_failure",
  "planner_failure": {"robot": 3, "time": 7.0, "goal": [1.0, 2.0], "position": [3.0, 4.0]},
  "left_environment": {"robot": 2, "time": 8.0, "goal": [5.0, 6.0], "position": [7.0, 8.0]},
  "events": 4321, "seed": 77, "provenance": {"version": "9.9.9"}
})");

// known_run() as a sweep's runs/<i>.json holds it (runs.csv's columns), written out by hand.
const ojson kKnownRun = ojson::parse(R"({
  "converged": true, "sim_time": 12.5, "cost_virtual": 0.11, "cost_real": 0.12,
  "cost_real_in_virtual_partition": 0.13, "path_length": 9.5, "time_to_10_percent": 3.25,
  "time_to_5_percent": 4.25, "time_to_1_percent": 5.25, "cost_to_best": 1.0625,
  "messages_sent": 21, "messages_delivered": 22, "messages_lost": 23,
  "messages_unreachable": 24, "info_age_mean": 0.5, "info_age_max": 1.5,
  "area_claimed_by_none": 0.25, "area_claimed_by_several": 0.125, "connected_fraction": 0.875,
  "algebraic_connectivity_min": null, "events": 4321, "stop_reason": "planner_failure",
  "target_outside_steps": 31, "stalled_time": 0.75, "centroid_distance": 0.0125,
  "planner_step_time": 2.5, "wall_time": 3.5, "fingerprint": "0123456789abcdef",
  "delivery_ratio": 1.0476190476190477, "latency_mean": 0.5, "latency_p95": 0.75,
  "channel_occupancy": 0.25, "phy_drops": 32, "gap_min": -0.005, "contact_time": 1.5,
  "wall_contacts": 3, "deadlocks": 4, "deadlock_time": 2.25, "turn_time": 6.5,
  "localization_error": 0.003, "known": "none", "known_fraction": 0.875,
  "mapping_time_90": 10.5, "map_disagreement": 0.0625, "map_bytes": 4096, "cost_ratio": 1.25,
  "loop_ratio": 10.0
})");

// docs/outputs.md's table of measures, as measures() gives it.
std::string measures_table() {
  std::string out =
      "| measure | unit | final.json | runs.csv | summary.csv | description |\n"
      "|---|---|---|---|---|---|\n";
  for (const Measure& m : measures()) {
    out += "| `" + m.name + "` | " + m.unit + " | " + (m.in_final() ? "yes" : "") + " | " +
           (m.run_place ? "`" + m.column() + "`" : "") + " | " + (m.summarized ? "yes" : "") +
           " | " + m.description + " |\n";
  }
  return out;
}
}  // namespace

TEST_CASE("each field reads the value its run holds", "[fields]") {
  const RunMeasures run = known_run();
  const nlohmann::json known = kKnownFinal;  // at_path reads nlohmann::json
  for (const auto& f : final_fields()) {
    INFO(f.name);
    const nlohmann::json* want = at_path(known, f.name);
    REQUIRE(want != nullptr);
    CHECK(nlohmann::json(f.get(run.outcome)) == *want);
  }
  CHECK(final_json(run.outcome) == kKnownFinal.dump(2) + "\n");
  for (const auto& f : run_fields()) {
    INFO(f.name);
    REQUIRE(kKnownRun.contains(f.name));
    CHECK(f.get(run) == kKnownRun.at(f.name));
  }
  // Every key, in order.
  CHECK(to_json_object(run_fields(), run) == kKnownRun);
}

TEST_CASE("final.json read back gives the outcome it was written from", "[fields]") {
  const RunMeasures run = known_run();
  const nlohmann::json written = nlohmann::json::parse(final_json(run.outcome));
  CoverageOutcome back;
  for (const auto& f : final_fields()) {
    INFO(f.name);
    REQUIRE(f.set);
    f.set(back, *at_path(written, f.name));
  }
  CHECK(final_json(back) == final_json(run.outcome));
}

TEST_CASE("every measure is recorded, once, with a description and its unit", "[fields]") {
  std::set<std::string> seen_names, seen_columns;
  std::vector<std::string> in_final;
  for (const Measure& m : measures()) {
    INFO(m.name);
    CHECK(seen_names.insert(m.name).second);
    CHECK_FALSE(m.description.empty());
    // Of the outcome (final.json) or of a sweep's run only, never both or neither.
    CHECK(m.in_final() != static_cast<bool>(m.of_run));
    CHECK((m.in_final() || m.run_place));
    if (m.run_place) CHECK(seen_columns.insert(m.column()).second);
    CHECK((!m.summarized || m.run_place));
    if (m.in_final()) in_final.push_back(m.name);
    const bool timed = m.name.find("time") != std::string::npos;
    if (timed && m.kind == FieldKind::number) CHECK_FALSE(m.unit.empty());
  }
  // The derived tables: final.json's fields are the measures of the outcome; runs.csv's
  // places are 0 to N-1 (run_fields() throws otherwise).
  CHECK(names(final_fields()) == in_final);
  REQUIRE_NOTHROW(run_fields());
  CHECK(run_fields().size() == seen_columns.size());
  // final.json as written holds each measure of the outcome at its path, and nothing else.
  CoverageOutcome o;
  o.robots.resize(2);
  std::vector<std::string> written;
  flatten(ojson::parse(final_json(o)), "", written);
  CHECK(written == in_final);
}

TEST_CASE("robots and metrics samples: every field described, timed ones with units", "[fields]") {
  const auto check = [](const auto& table) {
    for (const auto& f : table) {
      INFO(f.name);
      CHECK_FALSE(f.description.empty());
      const bool timed = f.name.find("time") != std::string::npos || f.name == "t";
      if (timed && f.kind == FieldKind::number) CHECK_FALSE(f.unit.empty());
    }
  };
  check(robot_fields());
  check(metrics_fields());
}

TEST_CASE("docs/outputs.md lists final.json's fields in the table's order", "[fields]") {
  const std::string text = test::doc_text("outputs.md");
  const auto at = text.find("```json\n", text.find("## final.json"));
  REQUIRE(at != std::string::npos);
  const auto end = text.find("```", at + 8);
  const auto example = ojson::parse(text.substr(at + 8, end - at - 8));
  std::vector<std::string> documented;
  flatten(example, "", documented);
  CHECK(documented == names(final_fields()));
  std::vector<std::string> robot;
  flatten(example["robots"][0], "", robot);
  CHECK(robot == names(robot_fields()));
}

TEST_CASE("docs/outputs.md's table of measures is the table's", "[fields]") {
  const std::string text = test::doc_text("outputs.md");
  INFO("docs/outputs.md should hold:\n" << measures_table());
  const auto at = text.find("| measure | unit |");
  REQUIRE(at != std::string::npos);
  const auto end = text.find("\n\n", at);
  CHECK(text.substr(at, end - at + 1) == measures_table());
}

TEST_CASE("docs/outputs.md gives trajectory.csv's and metrics.csv's headers", "[fields]") {
  const std::string text = test::doc_text("outputs.md");
  const auto trajectory = test::code_span_starting(text, "t,robot");
  REQUIRE(trajectory);
  CHECK(*trajectory == trajectory_header());
  const auto metrics = test::code_span_starting(text, "t,cost_real");
  REQUIRE(metrics);
  CHECK(*metrics == csv_header(metrics_fields()));
}
