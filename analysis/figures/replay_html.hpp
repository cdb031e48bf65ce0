#pragma once
// DIR/replay.html: a self-contained page (no network, no files besides itself) that plays a
// run back with a time slider, showing Ω, the robots and their paths so far, the virtual
// generators, the virtual and real targets, and the Voronoi cells of the generators the
// controller partitions (the virtual generators; the real positions for the baselines,
// whose virtual generators follow them).
//
// Opened with "?selftest" the page moves its own slider (as a user would: by setting the
// value and sending an input event), draws, and writes what it drew, or any error, into
// the element #status; tests read it from a headless browser.
#include <cstddef>
#include <string>

#include "analysis/records/run_files.hpp"

namespace covsim {

// At most max_frames frames (evenly spaced motion steps, the last one always included).
std::string replay_html(const RunFiles& run, std::size_t max_frames = 1500);

}  // namespace covsim
