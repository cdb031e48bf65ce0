#pragma once
// DIR/final.json: the outcome of a run (see docs/outputs.md).
#include <string>

#include "sim/coverage_run.hpp"

namespace covsim {

std::string final_json(const CoverageOutcome& outcome);

}  // namespace covsim
