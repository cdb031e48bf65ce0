#include <catch2/catch.hpp>

#include <string>

#include "scenarios/scenario.hpp"
#include "scenarios/scenario_description.hpp"
#include "scenarios/scenario_error.hpp"

using namespace covsim;

namespace {

Scenario with_recording(const std::string& recording) {
  const nlohmann::json j = nlohmann::json::parse(
      R"({"environment": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]]},
          "density": {"type": "uniform"}, "robots": {"positions": [[1, 1], [3, 3]]},
          "seed": 1, "recording": )" +
      recording + "}");
  return parse_scenario(j, "rec.json", ".");
}

}  // namespace

TEST_CASE("recording.compress is a boolean, false unless given", "[scenario][recording]") {
  CHECK_FALSE(with_recording("{}").recording.compress);
  CHECK_FALSE(with_recording(R"({"compress": false})").recording.compress);
  const Scenario s = with_recording(R"({"compress": true, "trajectory_period": 0.5})");
  CHECK(s.recording.compress);
  CHECK(s.recording.trajectory_period == 0.5);
  // covsim describe writes it out, and the description loads back to the same setting.
  const nlohmann::json described = describe_scenario(s);
  CHECK(described.at("recording").at("compress") == true);
  CHECK(parse_scenario(described, "described", ".").recording.compress);
  CHECK(describe_scenario(with_recording("{}")).at("recording").at("compress") == false);
}

TEST_CASE("recording.compress other than true or false is refused, naming its path",
          "[scenario][recording]") {
  for (const char* bad : {"1", "0", R"("yes")", "null", "[true]"}) {
    INFO(bad);
    try {
      with_recording(std::string(R"({"compress": )") + bad + "}");
      FAIL("accepted");
    } catch (const ScenarioError& e) {
      CHECK(e.path() == "$.recording.compress");
      CHECK_THAT(std::string(e.what()),
                 Catch::StartsWith("rec.json: $.recording.compress: expected true or false"));
    }
  }
  CHECK_THROWS_WITH(with_recording(R"({"compresss": true})"),
                    Catch::Contains("$.recording") && Catch::Contains("compresss"));
}

TEST_CASE("metrics.algebraic_connectivity_robots is a count, 2000 unless given",
          "[scenario][metrics]") {
  const auto with_metrics = [](const std::string& metrics) {
    const nlohmann::json j = nlohmann::json::parse(
        R"({"environment": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]]},
            "density": {"type": "uniform"}, "robots": {"positions": [[1, 1], [3, 3]]},
            "seed": 1, "metrics": )" +
        metrics + "}");
    return parse_scenario(j, "m.json", ".");
  };
  CHECK(with_metrics("{}").coverage.algebraic_connectivity_robots == 2000);
  const Scenario s = with_metrics(R"({"algebraic_connectivity_robots": 0, "period": 0.25})");
  CHECK(s.coverage.algebraic_connectivity_robots == 0);
  CHECK(s.coverage.sample_period == SimTime::from_seconds(0.25));
  const nlohmann::json described = describe_scenario(s);
  CHECK(described.at("metrics").at("algebraic_connectivity_robots") == 0);
  CHECK(parse_scenario(described, "described", ".").coverage.algebraic_connectivity_robots == 0);
  for (const char* bad : {"-1", "1.5", R"("all")", "null", "1e30"}) {
    INFO(bad);
    CHECK_THROWS_WITH(
        with_metrics(std::string(R"({"algebraic_connectivity_robots": )") + bad + "}"),
        Catch::StartsWith("m.json: $.metrics.algebraic_connectivity_robots: "));
  }
}
