#pragma once
// A data rectangle mapped onto a rectangle of a picture, with its frame, ticks and labels:
// the scene's axes in metres and every chart's.
#include <string>
#include <string_view>
#include <vector>

#include "analysis/figures/canvas.hpp"

namespace covsim {

// A tick step of 1, 2 or 5 times a power of ten, giving about `ticks` ticks over `range`.
double tick_step(double range, int ticks);

struct Axes {
  Box data;            // x and y ranges in data units
  Vec2 lo, hi;         // the picture rectangle: lo top-left, hi bottom-right
  bool log_y = false;  // y on a base-10 log scale (data.lo.y > 0)
  bool log_x = false;  // x on a base-10 log scale (data.lo.x > 0)
  // Categories along x instead of numbers: category k at x = k, its name as the tick.
  std::vector<std::string> x_categories;
  Vec2 to_px(Vec2 d) const;
  double px_per_unit() const { return (hi.x - lo.x) / (data.hi.x - data.lo.x); }
};

// Axes over `data` rounded out to ticks (to decades on a log axis), filling the picture
// rectangle.
Axes chart_axes(Box data, Vec2 lo, Vec2 hi, bool log_y = false, bool log_x = false);
// Axes with `categories` along x (from -0.5 to their count - 0.5) and `data`'s y range
// rounded out to ticks.
Axes category_axes(std::vector<std::string> categories, Box data, Vec2 lo, Vec2 hi);
// Axes for a map: x and y in the same scale, `data` centred in the picture rectangle.
Axes map_axes(Box data, Vec2 lo, Vec2 hi);

// The frame, light grid lines (if `grid`), ticks with their values, and the labels, in text
// of `font` points.
void draw_axes(Canvas& c, const Axes& a, std::string_view x_label, std::string_view y_label,
               bool grid, double font);
// The room draw_axes takes left of the frame (ticks, their values, the y label) and below it.
// The ticks depend on the data only, so Axes over any rectangle give the room.
double axes_left_room(const Axes& a, double font);
double axes_bottom_room(double font);

}  // namespace covsim
