#include "analysis/figures/figure_size.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>

namespace covsim {

namespace {
// A widescreen slide, 13.33 × 7.5 in: 960 × 540 pt, so that a PNG at two pixels per point is
// 1920 × 1080.
constexpr double kSlideWidth = 25.4 * 40.0 / 3.0, kSlideHeight = 25.4 * 7.5;
constexpr std::array<SizePreset, 3> kPresets = {{
    {"column", 88.0, 0.0, 8.0, "one column of a two-column paper (IEEE, ACM)"},
    {"page", 180.0, 0.0, 9.0, "the text width of a page"},
    {"talk", kSlideWidth, kSlideHeight, 16.0, "a 16:9 slide, filled"},
}};
constexpr std::string_view kDefault = "page";
constexpr double kLeast = 30.0, kMost = 1000.0;  // mm

FigureSize of(const SizePreset& p) {
  return {mm_to_pt(p.width_mm), mm_to_pt(p.height_mm), p.font_pt};
}
}  // namespace

std::span<const SizePreset> size_presets() {
  return kPresets;
}

std::string figure_size_choices() {
  std::string out;
  for (const SizePreset& p : kPresets)
    out += std::string(p.name) + ", ";
  return fmt::format("{}or a width such as 120mm ({:g} to {:g} mm)", out, kLeast, kMost);
}

double mm_to_pt(double mm) {
  return mm * 72.0 / 25.4;
}

const SizePreset& default_size_preset() {
  for (const SizePreset& p : kPresets)
    if (p.name == kDefault) return p;
  return kPresets.front();
}

FigureSize default_figure_size() {
  return of(default_size_preset());
}

std::optional<FigureSize> parse_figure_size(std::string_view text) {
  for (const SizePreset& p : kPresets)
    if (text == p.name) return of(p);
  if (text.size() < 3 || text.substr(text.size() - 2) != "mm") return std::nullopt;
  double mm = 0;
  const char* end = text.data() + text.size() - 2;
  const auto [at, ec] = std::from_chars(text.data(), end, mm);
  if (ec != std::errc() || at != end || !std::isfinite(mm) || mm < kLeast || mm > kMost)
    return std::nullopt;
  FigureSize size = default_figure_size();
  size.width = mm_to_pt(mm);
  return size;
}

}  // namespace covsim
