#pragma once
// DIR/replay.html: a self-contained page (no network, no files besides itself) that plays a
// run back with a time slider, titled with the scenario's name, showing Ω with axes and a
// scale bar, the robots in the figures' colours and their paths so far, the virtual
// generators, the virtual and real targets, and the Voronoi cells of the generators the
// controller partitions (the virtual generators; the real positions for the baselines,
// whose virtual generators follow them); beside the map the cost plot and the key, laid out
// to fit the window. The address's #t=SECONDS opens it at that time. Where the planners kept
// maps of their own (planner_map.csv), a menu picks a robot whose planner's walls and way
// ahead are drawn as they were at each frame's time.
//
// Opened with "?selftest" the page moves its own slider (as a user would: by setting the
// value and sending an input event), draws, and writes what it drew, or any error, into
// the element #status; tests read it from a headless browser.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "analysis/records/run_files.hpp"

namespace covsim {

// At most max_frames frames (evenly spaced motion steps, the last one always included).
// planner_robot: whose planner's map the page shows first (none if unset).
std::string replay_html(const RunFiles& run, std::size_t max_frames = 1500,
                        std::optional<std::uint32_t> planner_robot = std::nullopt);

}  // namespace covsim
