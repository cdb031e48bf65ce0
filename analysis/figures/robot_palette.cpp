#include "analysis/figures/robot_palette.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace covsim {

namespace {
// Paul Tol's muted scheme in his order (personal.sron.nl/~pault: rose, indigo, sand, green,
// cyan, wine, teal, olive, purple), without its pale grey, which reads as "no data".
constexpr std::array<std::uint32_t, 9> kMuted = {0xcc6677, 0x332288, 0xddcc77, 0x117733, 0x88ccee,
                                                 0x882255, 0x44aa99, 0x999933, 0xaa4499};
// Each round mixes the hues towards black (< 0) or white (> 0). The steps were searched (in
// 0.05s) for the largest least CIELAB distance among the first 40 robots (ΔE ≥ 12; all 54:
// ≥ 6), lighter steps short of white so that light hues stay visible on white paper.
constexpr std::array<double, 6> kRounds = {0.0, -0.5, 0.4, -0.25, -0.75, 0.2};
}  // namespace

std::size_t robot_hues() {
  return kMuted.size();
}

std::size_t distinct_robot_colours() {
  return kMuted.size() * kRounds.size();
}

Colour robot_colour(std::size_t i) {
  const Colour base = Colour::hex(kMuted[i % kMuted.size()]);
  const double mix = kRounds[(i / kMuted.size()) % kRounds.size()];
  const double towards = mix < 0 ? 0.0 : 1.0, f = std::abs(mix);
  const auto step = [&](double v) { return v + f * (towards - v); };
  return {step(base.r), step(base.g), step(base.b), 1.0};
}

std::string colour_hex(Colour c) {
  const auto byte = [](double v) {
    return static_cast<int>(std::lround(255 * std::clamp(v, 0.0, 1.0)));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

}  // namespace covsim
