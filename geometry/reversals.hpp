#pragma once
// Where a path walks back over the ground it has just covered: a wall walked back and forth.
// A reversal is a turn after which the path runs back along the way it came, staying within
// `tolerance` of it, for at least `min_length`. A robot that goes round a thin wall's end,
// or down one face of a slot and up the other, passes beside its earlier ground, not over
// it; a zigzag of range noise shorter than `min_length` is not counted either.
#include <cstddef>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

// The positions of `path` at which it turns back (the last position of the turn, where the
// way back begins), in order.
std::vector<std::size_t> reversals(const std::vector<Vec2>& path, double min_length,
                                   double tolerance);

}  // namespace covsim
