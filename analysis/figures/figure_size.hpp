#pragma once
// How large a figure is and how large its text: presets for a paper's column, its page and
// a slide, declared once here (the option parser, its help and the check of docs/outputs.md
// read this table), or a width in millimetres.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace covsim {

struct SizePreset {
  std::string_view name;
  double width_mm;
  double height_mm;  // 0: the figure's own, from Ω's aspect or the chart's
  double font_pt;    // the text's size: ticks, legend, labels
  std::string_view use;
};
std::span<const SizePreset> size_presets();
// What --size takes, for messages and help: "column, page, talk or a width such as 120mm
// (30 to 1000 mm)".
std::string figure_size_choices();

struct FigureSize {
  double width = 0;   // points
  double height = 0;  // points; 0: the figure's own
  double font = 0;    // points
  // A unit for marks, line widths and gaps that grows with the text (1 at 10 pt).
  double unit() const { return font / 10.0; }
};

double mm_to_pt(double mm);
// The preset figures take when none is asked for: page.
const SizePreset& default_size_preset();
FigureSize default_figure_size();
// A preset's name or a width such as "120mm" (the default preset's font); nullopt for
// anything else, or a width outside [30, 1000] mm.
std::optional<FigureSize> parse_figure_size(std::string_view text);

}  // namespace covsim
