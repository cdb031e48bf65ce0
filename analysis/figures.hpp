#pragma once
// The pictures of a run, next to which the paper's Figures 3 and 4 can be put.
#include <string>
#include <vector>

#include "analysis/coverage_run.hpp"
#include "analysis/run_recorder.hpp"

namespace covsim {

// Ω with its obstacles (black), the density as yellow shading, the virtual generators'
// paths (green, dashed) and the robots' paths (dark blue), the virtual generators' final
// partition (blue) and the last partition of the real positions (red), virtual targets
// (red crosses), projected real targets (yellow crosses), start (hollow) and final (filled)
// positions.
std::string scene_svg(const Scenario& scenario, const CoverageOutcome& outcome,
                      const std::vector<std::vector<Vec2>>& real_paths,
                      const std::vector<std::vector<Vec2>>& virtual_paths);
// The cost H of the real and the virtual generators over time.
std::string cost_svg(const std::vector<MetricsSample>& samples);

}  // namespace covsim
