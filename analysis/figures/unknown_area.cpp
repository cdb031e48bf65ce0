#include "analysis/figures/unknown_area.hpp"

namespace covsim {

void shade_unknown(Canvas& c, const MapView& view, const KnownCells& known, double t,
                   std::optional<std::uint32_t> robot) {
  const double half = 0.5 * known.size;
  for (std::size_t n = 0; n < known.cells.size(); ++n) {
    const KnownCell& k = known.cells[n];
    const double since = robot ? known.robots.at(*robot)[n] : k.since;
    if (since > t || std::isinf(since))
      c.rectangle(view.to_px(Vec2{k.centre.x - half, k.centre.y + half}),
                  view.to_px(Vec2{k.centre.x + half, k.centre.y - half}), Marks::unknown());
  }
}

}  // namespace covsim
