#include "analysis/figures/marks.hpp"

#include <string>

namespace covsim {

Colour Marks::ink() {
  return Colour::hex(0x222222);
}
Colour Marks::obstacle() {
  return Colour::hex(0x4a4a4a);
}
Colour Marks::unknown() {
  return Colour::hex(0x6b7a99, 0.45);
}
Colour Marks::virtual_cell() {
  return Colour::hex(0x1f5fbf);
}
Colour Marks::real_cell() {
  return Colour::hex(0xd62728);
}
Colour Marks::projected() {
  return Colour::hex(0xffd21f);
}

Stroke Marks::path(Colour c) const {
  return {c, 1.6 * u};
}
Stroke Marks::planner_wall() const {
  return {Colour::hex(0xd95f02), 1.6 * u};
}
Stroke Marks::planner_way(Colour c) const {
  return {c, 1.2 * u, {3.0 * u, 2.0 * u}};
}
Stroke Marks::virtual_path(Colour c) const {
  return {Colour{c.r, c.g, c.b, 0.6}, 0.8 * u, {3.0 * u, 2.5 * u}};
}
Stroke Marks::cells() const {
  return {virtual_cell(), 1.2 * u};
}
Stroke Marks::real_cells() const {
  return {real_cell(), 1.2 * u, {5.0 * u, 3.0 * u}};
}

void Marks::start(Canvas& c, Vec2 p, Colour col) const {
  c.circle(p, 4.0 * u, Colour::hex(0xffffff), Stroke{col, 1.3 * u});
}
void Marks::robot(Canvas& c, Vec2 p, Colour col) const {
  c.circle(p, 4.0 * u, col, Stroke{Colour::hex(0xffffff), 1.0 * u});
}
void Marks::body(Canvas& c, Vec2 p, double radius, Colour col) const {
  if (radius <= 4.0 * u) {
    robot(c, p, col);  // smaller than the mark: the mark
    return;
  }
  Colour fill = col;
  fill.a = 0.35;
  c.circle(p, radius, fill, Stroke{col, 1.2 * u});
  c.circle(p, 1.6 * u, col);
}
void Marks::generator(Canvas& c, Vec2 p, Colour col) const {
  c.square(p, 2.4 * u, col, Stroke{Colour::hex(0xffffff), 0.6 * u});
}
void Marks::target(Canvas& c, Vec2 p) const {
  c.cross(p, 3.6 * u, Stroke{ink(), 1.2 * u});
}
void Marks::projected_target(Canvas& c, Vec2 p) const {
  c.cross(p, 5.2 * u, Stroke{Colour::hex(0x000000), 3.2 * u});
  c.cross(p, 5.2 * u, Stroke{projected(), 1.6 * u});
}
void Marks::id(Canvas& c, Vec2 p, std::size_t robot, double font) const {
  c.text(p + Vec2{5.5 * u, -5.0 * u}, std::to_string(robot), font, ink());
}

}  // namespace covsim
