// H's unit is the one the measures table declares (kCostUnit), wherever H is given: every
// cost measure and column, and the pages and scripts that label H, which spell it the same
// way and no other.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "analysis/records/measure.hpp"
#include "analysis/records/result_fields.hpp"

using namespace covsim;

namespace {
std::string source_text(const std::string& path) {
  std::ifstream in(std::string(COVSIM_SOURCE_DIR) + "/" + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
// A value of H, by what it says it is (cost_to_best, a ratio of two, is not one).
bool is_cost(const std::string& description) {
  return description.rfind("H of ", 0) == 0;
}
}  // namespace

TEST_CASE("every cost measure and column is in the declared unit", "[cost_unit]") {
  CHECK(std::string(kCostUnit) == "m⁴·φ");
  int costs = 0;
  const auto check = [&](const std::string& name, const std::string& unit,
                         const std::string& description) {
    INFO(name << ": " << description);
    CHECK((unit == kCostUnit) == is_cost(description));
    costs += is_cost(description) ? 1 : 0;
  };
  for (const Measure& m : measures())
    check(m.name, m.unit, m.description);
  for (const auto& f : run_fields())
    check(f.name, f.unit, f.description);
  for (const auto& f : metrics_fields())
    check(f.name, f.unit, f.description);
  CHECK(costs >= 9);  // three measures, three runs.csv and three metrics.csv columns
}

TEST_CASE("the pages and the scripts that label H use the declared unit", "[cost_unit]") {
  const std::string unit = kCostUnit;
  // The Python figure labels its axis as the C++ cost figure does.
  CHECK_THAT(source_text("examples/python/fig3.py"), Catch::Contains("\"cost H [" + unit + "]\""));
  for (const char* path : {"docs/outputs.md", "docs/python.md", "examples/python/fig3.py",
                           "python/covsim/__init__.py", "python/src/geometry_binding.cpp"}) {
    INFO(path);
    const std::string text = source_text(path);
    REQUIRE_FALSE(text.empty());
    // Other spellings of the unit, or the old one.
    for (const char* other : {"m⁴ φ", "m^4", "m4·φ", "m⁴φ", "weight · m²", "m⁴·phi"})
      CHECK_THAT(text, !Catch::Contains(other));
  }
  CHECK_THAT(source_text("docs/outputs.md"), Catch::Contains("H is in " + unit + " everywhere"));
}
