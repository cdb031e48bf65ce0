#include "apps/figure_options.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "analysis/figures/figure_size.hpp"
#include "apps/input_error.hpp"

namespace covsim::app {

namespace {
constexpr double kFontLeast = 4, kFontMost = 48;  // points

// --size's help, from the table of presets.
std::string size_help() {
  std::string out = "Figure size and text:";
  for (const SizePreset& p : size_presets()) {
    out += fmt::format(" {} ({:.4g} mm", p.name, p.width_mm);
    if (p.height_mm > 0) out += fmt::format(" × {:.4g} mm", p.height_mm);
    out += fmt::format(", {:g} pt: {}),", p.font_pt, p.use);
  }
  return fmt::format("{} or a width such as 120mm (default {})", out, default_size_preset().name);
}
}  // namespace

void FigureOptions::add_to(CLI::App* cmd, const std::string& figures) {
  cmd->add_option("--format", format, "Figures (" + figures + ") as svg, pdf or png")
      ->check(CLI::IsMember({"svg", "pdf", "png"}))
      ->capture_default_str();
  cmd->add_option("--png-width", png_width,
                  "PNG figures this many pixels wide (default: two pixels per point)")
      ->check(CLI::Range(64, 16384));
  cmd->add_option("--size", size, size_help());
  cmd->add_option("--font-size", font_size, "Text size in points (default: the size's)")
      ->check(CLI::Range(kFontLeast, kFontMost));
  cmd->add_option("--layers", layers,
                  "What the figures and the video draw, a comma list (default all): " +
                      layer_names() + "; all,-NAME draws all but NAME");
  cmd->add_option("--video", video, "Also encode the run as a video (FILE.mp4 or FILE.gif)");
  cmd->add_option("--fps", video_options.fps, "Video frames per second")
      ->check(CLI::Range(1.0, 240.0))
      ->capture_default_str();
  cmd->add_option("--speed", video_options.speedup,
                  "Simulated seconds per second of video (default: the run in about 20 s)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--video-width", video_options.width, "Video width in pixels")
      ->check(CLI::Range(160, 3840))
      ->capture_default_str();
}

FigureFile FigureOptions::file() const {
  FigureFile out{*parse_figure_format(format), png_width, default_figure_size()};
  if (!size.empty()) {
    const auto parsed = parse_figure_size(size);
    if (!parsed)
      throw InputError(
          fmt::format("--size: expected {}, found \"{}\"", figure_size_choices(), size));
    out.size = *parsed;
  }
  if (font_size > 0) out.size.font = font_size;
  return out;
}

Layers FigureOptions::drawn() const {
  if (layers.empty()) return Layers::all();
  try {
    return parse_layers(layers);
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("--layers: {}", e.what()));
  }
}

VideoOptions FigureOptions::video_settings() const {
  VideoOptions out = video_options;
  out.layers = drawn();
  out.progress = true;
  return out;
}

void FigureOptions::check() const {
  file();
  drawn();
  if (video.empty()) return;
  try {
    check_video_file(video);
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("--video: {}", e.what()));
  }
}

}  // namespace covsim::app
