#pragma once
#include <stdexcept>
#include <string>

namespace covsim {

// A scenario (or other input file) that cannot be used. The message reads
// "FILE: $.json.path: what was expected", or "FILE:LINE:COLUMN: ..." for malformed JSON.
struct ScenarioError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace covsim
