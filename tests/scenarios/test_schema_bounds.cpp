// Every bound of every parameter schema (each component's parameters, each fixed section's
// keys) appears in the error for a value beyond it, with the unit: "expected a number > 0
// and <= 1000 Hz, found 1000000000", never only "a positive number".
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <string>

#include "core/param_schema.hpp"
#include "scenarios/component_sections.hpp"
#include "scenarios/scenario_sections.hpp"

using namespace covsim;

namespace {

std::string number(double v) {
  return fmt::format("{}", v);
}

// Checks the message for a value just past each bound of `spec` (and of its fields); the
// count of bounds checked.
std::size_t check_bounds(const std::string& where, const ParamSpec& spec) {
  std::size_t checked = 0;
  for (const ParamSpec& f : spec.fields)
    checked += check_bounds(where + "." + f.name, f);
  if (spec.kind != ParamKind::number && spec.kind != ParamKind::integer) return checked;
  const auto beyond = [&](double bound, bool upper) -> std::optional<ParamValue> {
    if (spec.kind == ParamKind::integer) {
      if (!upper && bound <= 0.0) return std::nullopt;  // nothing below 0 is a whole number
      const double v = upper ? std::floor(bound) + 1.0 : std::ceil(bound) - 1.0;
      return ParamValue{static_cast<std::uint64_t>(v)};
    }
    const double step = std::max(1.0, std::fabs(bound));
    return ParamValue{upper ? bound + step : bound - step};
  };
  for (const bool upper : {false, true}) {
    const std::optional<double> bound = upper ? spec.max : spec.min;
    if (!bound) continue;
    const auto value = beyond(*bound, upper);
    if (!value) continue;
    INFO(where << " = " << to_text(*value));
    const std::string message = check_param(spec, *value);
    CHECK_THAT(message, Catch::StartsWith("expected "));
    if (spec.min)
      CHECK_THAT(message, Catch::Contains((spec.min_exclusive ? "> " : ">= ") + number(*spec.min)));
    if (spec.max)
      CHECK_THAT(message, Catch::Contains((spec.max_exclusive ? "< " : "<= ") + number(*spec.max)));
    if (!spec.unit.empty()) CHECK_THAT(message, Catch::Contains(" " + spec.unit + ","));
    CHECK_THAT(message, Catch::EndsWith("found " + to_text(*value)));
    ++checked;
  }
  return checked;
}

}  // namespace

TEST_CASE("every bound in the parameter schemas is named in its error", "[schema]") {
  std::size_t checked = 0;
  for_each_component_section([&](const auto& section) {
    for (const auto& entry : section.registry().entries())
      for (const ParamSpec& spec : entry.params)
        checked += check_bounds(section.path + "(" + entry.name + ")." + spec.name, spec);
  });
  for (const ScenarioSection& section : scenario_sections())
    for (const ParamSpec& spec : section.schema())
      checked += check_bounds(section.path + "." + spec.name, spec);
  // The schemas hold many bounds: a walk that checked few would have missed them.
  CHECK(checked > 100);
}

TEST_CASE("a bound is named with its unit where the value is read", "[schema]") {
  // The reproduction: a tracking rate of 1e9 Hz.
  const ParamSpec rate = ParamSpec::number("rate", "Hz", "").positive().at_most(1000.0);
  CHECK(check_param(rate, 1e9) == "expected a number > 0 and <= 1000 Hz, found 1000000000");
  const ParamSpec window = ParamSpec::integer("stall_window", "steps", "").at_least(1).at_most(1e6);
  CHECK(check_param(window, std::uint64_t{1'000'000'000}) ==
        "expected a whole number >= 1 and <= 1000000 steps, found 1000000000");
}
