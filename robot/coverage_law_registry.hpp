#pragma once
// The registry of coverage laws: a scenario's "controller": {"type": NAME, ...} names one.
#include "robot/coverage_law.hpp"

namespace covsim {

Registry<LawEntry>& coverage_law_registry();

// The law a configuration names; unknown types throw std::invalid_argument naming the
// registered ones.
std::unique_ptr<CoverageLaw> make_coverage_law(const LawConfig& config, const LawContext& context);

}  // namespace covsim
