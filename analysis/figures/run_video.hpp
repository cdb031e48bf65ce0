#pragma once
// A run as a video: frames drawn through the Canvas (Ω and the density, each robot's trail,
// its virtual generator and target, the virtual generators' current cells, a clock) piped
// to Debian's ffmpeg, which encodes MP4 (H.264) or GIF by the file's extension.
#include <filesystem>

#include "analysis/records/run_files.hpp"

namespace covsim {

struct VideoOptions {
  double fps = 25.0;
  // Simulated seconds per second of video; 0: the run fills about 20 s of video.
  double speedup = 0.0;
  int width = 960;        // pixels (the height follows Ω's aspect)
  bool progress = false;  // a progress bar on standard error
};

// The number of frames a run of `sim_time` seconds gives.
std::size_t video_frames(double sim_time, const VideoOptions& options);

// Writes `file` (.mp4 or .gif) only when ffmpeg succeeds (written to a partial file first).
// Throws std::runtime_error naming the problem: an unknown extension, ffmpeg missing or
// failing.
void write_run_video(const RunFiles& run, const std::filesystem::path& file,
                     const VideoOptions& options);

}  // namespace covsim
