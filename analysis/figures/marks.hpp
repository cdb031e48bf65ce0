#pragma once
// The marks a scene, a video frame and their legends draw, sized by one unit (1 at 10 pt
// text), so that a legend's symbol is the mark it explains.
#include <cstddef>

#include "analysis/figures/canvas.hpp"

namespace covsim {

struct Marks {
  double u = 1.0;

  static Colour ink();           // text, ticks, the virtual targets
  static Colour obstacle();      // obstacles and the outside of Ω
  static Colour unknown();       // what the robots' maps do not hold yet
  static Colour virtual_cell();  // the virtual generators' partition
  static Colour real_cell();     // the real positions' partition
  static Colour projected();     // a real target projected onto Ω

  Stroke path(Colour c) const;          // a robot's path
  Stroke virtual_path(Colour c) const;  // a virtual generator's path: thin, dashed
  Stroke cells() const;
  Stroke real_cells() const;
  Stroke planner_wall() const;         // a wall a planner's sensed map holds: dark orange
  Stroke planner_way(Colour c) const;  // the way a planner has ahead: dashed, in its colour
  void start(Canvas& c, Vec2 p, Colour col) const;  // hollow circle
  void robot(Canvas& c, Vec2 p, Colour col) const;  // filled circle with a white rim
  // A robot with a body of `radius` px drawn to scale: a translucent disk in its colour with
  // a solid rim and a dot at its centre; the robot's mark when the body is no larger than it
  // (points: radius 0).
  void body(Canvas& c, Vec2 p, double radius, Colour col) const;
  void generator(Canvas& c, Vec2 p, Colour col) const;  // square
  void target(Canvas& c, Vec2 p) const;                 // cross
  void projected_target(Canvas& c, Vec2 p) const;       // yellow cross, black rim
  // The robot's ID above right of its mark, in text of `font` points.
  void id(Canvas& c, Vec2 p, std::size_t robot, double font) const;
};

}  // namespace covsim
