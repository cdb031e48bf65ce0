#include "robot/coverage_law_registry.hpp"

#include "robot/euclidean_lloyd_law.hpp"
#include "robot/external_law.hpp"
#include "robot/geodesic_lloyd_law.hpp"
#include "robot/virtual_generators_law.hpp"

namespace covsim {

Registry<LawEntry>& coverage_law_registry() {
  static Registry<LawEntry> registry(
      "coverage law", {virtual_generators_entry(), euclidean_lloyd_entry(), geodesic_lloyd_entry(),
                       external_law_entry()});
  return registry;
}

std::unique_ptr<CoverageLaw> make_coverage_law(const LawConfig& config, const LawContext& context) {
  const LawEntry& e = coverage_law_registry().at(config.type);
  return e.make(context, with_defaults(e.params, config.params));
}

}  // namespace covsim
