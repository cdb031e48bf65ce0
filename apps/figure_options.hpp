#pragma once
// How a run's figures and video are drawn: the options `covsim run` and `covsim plot` share,
// under the same names (--format, --png-width, --size, --font-size, --layers, --video and the
// video's --fps, --speed, --video-width).
#include <CLI/CLI.hpp>

#include <string>

#include "analysis/figures/canvas.hpp"
#include "analysis/figures/layers.hpp"
#include "analysis/figures/run_video.hpp"

namespace covsim::app {

struct FigureOptions {
  std::string format = "svg";
  int png_width = 0;
  std::string size;  // as typed; empty: the default preset
  double font_size = 0;
  std::string layers;  // as typed; empty: all
  std::string video;   // empty: no video
  VideoOptions video_options;

  // Adds the options to a command; `figures` names what the command draws, for the help.
  void add_to(CLI::App* cmd, const std::string& figures);
  // Checks every option, so that bad input stops a command before it runs or writes
  // anything: InputErrors naming the option. Also checks that a video can be written.
  void check() const;
  // The figures' file, size and font, and the layers drawn (checked).
  FigureFile file() const;
  Layers drawn() const;
  // The video's options, with the layers and a progress line on a terminal.
  VideoOptions video_settings() const;
};

}  // namespace covsim::app
