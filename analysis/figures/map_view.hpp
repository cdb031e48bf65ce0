#pragma once
// Ω drawn on a picture: its obstacles, the density as a colour map with its colour bar, axes
// in metres and a scale bar. The scene and every video frame share it.
#include <string>

#include "analysis/figures/axes.hpp"
#include "analysis/figures/canvas.hpp"
#include "scenarios/scenario.hpp"

namespace covsim {

// Sequential colour map for densities: light (low) to dark orange (high), t in [0, 1].
Colour density_colour(double t);
// A colour per robot, repeating after 20.
Colour robot_colour(std::size_t i);

class MapView {
 public:
  // Ω's box (padded a little) fitted to the picture rectangle [lo, hi].
  MapView(const Scenario& scenario, Vec2 lo, Vec2 hi);
  const Axes& axes() const { return axes_; }
  Vec2 to_px(Vec2 world) const { return axes_.to_px(world); }
  double px_per_metre() const { return axes_.px_per_unit(); }
  std::vector<std::vector<Vec2>> to_px(const std::vector<std::vector<Vec2>>& rings) const;
  bool uniform() const { return uniform_; }
  // The density over Ω's box, row 0 at the top (empty when uniform).
  const Image& density_image() const { return density_; }

  // Obstacles, the density (clipped to Ω) and the axes.
  void draw_background(Canvas& c) const;
  // A vertical colour bar for the density in [lo, hi], labelled; nothing if it is uniform.
  void draw_colour_bar(Canvas& c, Vec2 lo, Vec2 hi) const;
  // A bar of a round length in metres at the bottom left of Ω's box.
  void draw_scale_bar(Canvas& c) const;

 private:
  const Scenario& scenario_;
  Axes axes_;
  Image density_;
  double density_max_ = 0.0;
  bool uniform_ = true;
};

}  // namespace covsim
