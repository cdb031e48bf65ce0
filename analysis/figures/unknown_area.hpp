#pragma once
// What the robots' maps do not hold yet, shaded over Ω: in the scene figure, the video and
// (in its own script) replay.html, for robots that mapped Ω.
#include <cstdint>
#include <optional>

#include "analysis/figures/canvas.hpp"
#include "analysis/figures/map_view.hpp"
#include "analysis/figures/marks.hpp"
#include "analysis/records/known_cells.hpp"

namespace covsim {

// Shades each cell not known by time t (every cell never known, for t infinite): to the
// robots' maps together, or to robot `robot`'s own (which known.robots must hold).
void shade_unknown(Canvas& c, const MapView& view, const KnownCells& known, double t,
                   std::optional<std::uint32_t> robot = std::nullopt);

}  // namespace covsim
