#pragma once
// One colour per robot, the same in the figures, the videos and the replay page: Paul Tol's
// "muted" scheme (nine colours told apart with the common colour-vision deficiencies), then
// the same nine hues darker and lighter, round by round, so that colours stay distinct past
// nine robots; the robots' IDs tell them apart where colours alone cannot.
#include <cstddef>
#include <string>

#include "analysis/figures/canvas.hpp"

namespace covsim {

// The number of hues before the rounds of darker and lighter ones start.
std::size_t robot_hues();
// How many robots get a colour no other robot has; beyond, colours repeat.
std::size_t distinct_robot_colours();
// Robot i's colour: hue i mod robot_hues(), in round i / robot_hues().
Colour robot_colour(std::size_t i);
// "#rrggbb", as HTML and SVG write colours.
std::string colour_hex(Colour c);

}  // namespace covsim
