#pragma once
// Ω drawn on a picture: its obstacles, the density as a colour map with its colour bar, axes
// in metres and a scale bar. The scene and every video frame share it.
#include <string>
#include <vector>

#include "analysis/figures/axes.hpp"
#include "analysis/figures/canvas.hpp"
#include "analysis/figures/layers.hpp"
#include "scenarios/scenario.hpp"

namespace covsim {

// Sequential colour map for densities: light (low) to dark orange (high), t in [0, 1].
Colour density_colour(double t);

class MapView {
 public:
  // Ω's box padded a little: the data a map shows.
  static Box extent(const Scenario& scenario);
  // The extent's height over its width, kept within [0.3, 1.6] (a map of a long corridor
  // still has room for its robots).
  static double aspect(const Scenario& scenario);

  // The extent fitted to the picture rectangle [lo, hi].
  MapView(const Scenario& scenario, Vec2 lo, Vec2 hi);
  // Not yet placed: a figure that lays itself out around the map places it when it knows
  // where (the colour bar's width, say, is known before).
  explicit MapView(const Scenario& scenario);
  void place(Vec2 lo, Vec2 hi);
  const Axes& axes() const { return axes_; }
  Vec2 to_px(Vec2 world) const { return axes_.to_px(world); }
  double px_per_metre() const { return axes_.px_per_unit(); }
  std::vector<std::vector<Vec2>> to_px(const std::vector<std::vector<Vec2>>& rings) const;
  bool uniform() const { return uniform_; }
  // The density over Ω's box, row 0 at the top (empty when uniform).
  const Image& density_image() const { return density_; }

  // Of `layers`: the obstacles and ∂Ω, the density (clipped to Ω) and the axes, in text of
  // `font` points.
  void draw_background(Canvas& c, const Layers& layers, double font) const;
  // The width of a vertical colour bar with its values and label in text of `font` points
  // (0 when the density is uniform), and the bar drawn in that width from `left`, between
  // `top` and `bottom`.
  double colour_bar_width(double font) const;
  // The colour bar's tick values: 0, then about four steps up to the density's maximum.
  std::vector<double> colour_bar_ticks() const;
  void draw_colour_bar(Canvas& c, double left, double top, double bottom, double font) const;
  // A legend symbol for the density: a swatch of its colours, or white (uniform).
  void draw_density_swatch(Canvas& c, Vec2 centre, double font) const;
  // A bar of a round length in metres at the bottom left of the map.
  void draw_scale_bar(Canvas& c, double font) const;

 private:
  const Scenario& scenario_;
  Axes axes_;
  Image density_;
  double density_max_ = 0.0;
  bool uniform_ = true;
};

}  // namespace covsim
