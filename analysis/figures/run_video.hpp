#pragma once
// A run as a video: frames drawn through the Canvas (Ω and the density, each robot's trail
// from its start, its virtual generator and target, the virtual generators' current cells, a
// legend and a clock: the layers asked for) piped to Debian's ffmpeg, which encodes MP4
// (H.264) or GIF by the file's extension.
#include <filesystem>
#include <optional>
#include <vector>

#include "analysis/figures/layers.hpp"
#include "analysis/records/known_cells.hpp"
#include "analysis/records/planner_map_record.hpp"
#include "analysis/records/robot_track.hpp"
#include "sim/coverage_run.hpp"

namespace covsim {

struct VideoOptions {
  double fps = 25.0;
  // Simulated seconds per second of video; 0: the run fills about 20 s of video.
  double speedup = 0.0;
  int width = 960;                // pixels (the height follows Ω's aspect)
  Layers layers = Layers::all();  // of these, what a frame shows (not virtual paths or real cells)
  const KnownCells* known = nullptr;  // robots that mapped Ω: what they did not know yet, shaded
  bool progress = false;              // a progress line on stderr, when it is a terminal
  // Planners that kept maps of their own: robot `planner_robot`'s walls and way ahead at each
  // frame's time.
  const PlannerMapRecord* planner_maps = nullptr;
  std::optional<std::uint32_t> planner_robot;
};

// The number of frames a run of `sim_time` seconds gives.
std::size_t video_frames(double sim_time, const VideoOptions& options);

// Throws std::runtime_error unless `file` can be written as a video: its extension is .mp4
// or .gif, and ffmpeg is on PATH. Checked before the work a video follows (a run).
void check_video_file(const std::filesystem::path& file);

// Writes `file` (.mp4 or .gif) only when ffmpeg succeeds (written to a partial file first).
// Throws std::runtime_error naming the problem: an unknown extension, ffmpeg missing or
// failing.
void write_run_video(const Scenario& scenario, const CoverageOutcome& outcome,
                     const std::vector<RobotTrack>& tracks, const std::filesystem::path& file,
                     const VideoOptions& options);

}  // namespace covsim
