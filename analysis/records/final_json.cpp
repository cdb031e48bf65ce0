#include "analysis/records/final_json.hpp"

#include "analysis/records/result_fields.hpp"

namespace covsim {

std::string final_json(const CoverageOutcome& o) {
  return to_json_object(final_fields(), o).dump(2) + "\n";
}

}  // namespace covsim
