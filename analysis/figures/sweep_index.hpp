#pragma once
// DIR/index.html: a sweep on one page, for a browser: its scenario, its settings and seeds,
// how its runs ended, the summary table (DIR/summary.csv) and every chart drawn.
#include <filesystem>
#include <vector>

#include "analysis/sweep/sweep_result.hpp"
#include "analysis/sweep/sweep_spec.hpp"

namespace covsim {

// Writes DIR/index.html (atomically) showing `charts`, files in DIR.
void write_sweep_index(const std::filesystem::path& dir, const SweepSpec& spec,
                       const std::vector<SweepResult>& results,
                       const std::vector<std::filesystem::path>& charts);

}  // namespace covsim
