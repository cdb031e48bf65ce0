// Overrides of a scenario (--set, a sweep's settings, Python's Scenario.set): switching a
// component's type keeps the old type's parameters aside instead of failing on them.
#include <catch2/catch.hpp>

#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"
#include "scenarios/scenario_override.hpp"

using namespace covsim;

namespace {
const std::string kEpuck = std::string(COVSIM_SOURCE_DIR) + "/scenarios/epuck_u_shape.json";
}  // namespace

TEST_CASE("switching a component's type sets the old type's parameters aside", "[scenario]") {
  // epuck_u_shape tracks its robots: {"type": "tracking", "rate": 10, "latency": 0.1, ...}.
  const Scenario exact = load_scenario(kEpuck, {parse_override("robots.localization.type=exact")});
  CHECK(exact.coverage.localization.type == "exact");
  // Back to tracking: the parameters set aside are its own again, the same as the file's.
  const Scenario back =
      load_scenario(kEpuck, {parse_override("robots.localization.type=exact"),
                             parse_override("robots.localization.type=tracking")});
  const Scenario file = load_scenario(kEpuck, {});
  CHECK(back.coverage.localization.type == "tracking");
  CHECK(back.coverage.localization.params == file.coverage.localization.params);
  CHECK(file.coverage.localization.params.number("latency") == 0.1);

  nlohmann::json j = {
      {"robots",
       {{"localization",
         {{"type", "tracking"}, {"latency", 0.1}, {"tracking", {{"latency", 0.3}}}}}}}};
  override_scenario(j, "robots.localization.type", "exact");
  // What the old type's block held stands; the key it shared is moved only where free.
  CHECK(j["robots"]["localization"] ==
        nlohmann::json({{"type", "exact"}, {"tracking", {{"latency", 0.3}}}}));
  // Other paths, unknown types and the same type change nothing but the value.
  nlohmann::json k = {{"robots", {{"localization", {{"type", "tracking"}, {"latency", 0.1}}}}}};
  override_scenario(k, "robots.localization.type", "tracking");
  CHECK(k["robots"]["localization"]["latency"] == 0.1);
  override_scenario(k, "robots.localization.type", "no_such_type");
  CHECK(k["robots"]["localization"]["latency"] == 0.1);
  override_scenario(k, "robots.localization.latency", 0.2);
  CHECK(k["robots"]["localization"]["latency"] == 0.2);
}
