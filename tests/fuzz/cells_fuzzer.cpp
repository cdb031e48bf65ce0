// libFuzzer target: {"scenario": {...}, "generators": [[x, y], ...]} as `covsim cells` reads
// them. Bad input must end in a ScenarioError or GeometryError; for good input the cells'
// masses must add up to Ω's mass (the partition covers Ω once).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "geometry/geometry_error.hpp"
#include "geometry/voronoi_partition.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace covsim;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json json = parse_json(text, "fuzz.json");
    const JsonValue root(json, "fuzz.json");
    root.only_keys({"scenario", "generators"});
    const Scenario s = parse_scenario(root.at("scenario").raw(), "fuzz.json", ".");
    std::vector<Vec2> generators = root.at("generators").points();
    if (generators.size() > 64) return 0;  // the cost of one case, not a defect
    const CellIntegrator integrator(*s.environment, *s.density);
    const VoronoiPartition partition(integrator, std::move(generators));
    double mass = 0.0;
    for (std::size_t i = 0; i < partition.size(); ++i)
      mass += partition.summary(i).mass;
    const double total = integrator.total_mass();
    if (!(std::abs(mass - total) <= 1e-6 * total)) std::abort();  // cells do not tile Ω
  } catch (const ScenarioError&) {
  } catch (const GeometryError&) {
  }
  return 0;
}
