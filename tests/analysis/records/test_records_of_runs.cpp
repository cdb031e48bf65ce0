// What the records say of particular runs: a planner failure in final.json, and a measure
// that was not computed as null in metrics.csv.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>

#include "analysis/records/final_json.hpp"
#include "analysis/records/result_fields.hpp"
#include "sim/metrics_sampler.hpp"
#include "tests/robot/paper_scenarios.hpp"
#include "tests/sim/gives_up_planner.hpp"

using namespace covsim;
using covsim::test::GivesUp;
using covsim::test::paper;

TEST_CASE("final.json names a planner failure, and null when there was none", "[records]") {
  const CoverageOutcome out =
      run_coverage(paper("two_obstacles.json"), nullptr, nullptr,
                   [](std::uint32_t) { return std::make_unique<GivesUp>(); });
  REQUIRE(out.planner_failure);
  const auto j = nlohmann::json::parse(final_json(out));
  CHECK(j["stop_reason"] == "planner_failure");
  CHECK(j["planner_failure"]["robot"] == 0);
  CHECK(j["planner_failure"]["time"].get<double>() == Approx(0.1));
  CHECK(nlohmann::json::parse(final_json(run_coverage(paper("l_shape.json"))))["planner_failure"]
            .is_null());
}

TEST_CASE("metrics.csv leaves the algebraic connectivity empty where it was not computed",
          "[records]") {
  // u_shape's 5 robots in range of each other; λ2 for at most 5 robots, then at most 4.
  nlohmann::json j = paper("u_shape.json").json;
  j["network"] = {{"range", 5.0}};
  const auto first_sample = [&](std::uint64_t limit) {
    j["metrics"] = {{"algebraic_connectivity_robots", limit}};
    const Scenario s = parse_scenario(j, "u_shape", std::string(COVSIM_SOURCE_DIR) + "/scenarios");
    MetricsSampler sampler;
    run_coverage(s, &sampler);
    REQUIRE_FALSE(sampler.samples().empty());
    return sampler.samples().front();
  };
  const MetricsSample with = first_sample(5), without = first_sample(4);
  bool found = false;
  for (const auto& f : metrics_fields()) {
    if (f.name != "algebraic_connectivity") continue;
    found = true;
    CHECK(f.get(with).is_number());
    CHECK(f.get(with).get<double>() == Approx(5.0));  // the complete graph's: n
    CHECK(f.get(without).is_null());
    CHECK(csv_cell(f.get(without)).empty());
  }
  CHECK(found);
}
