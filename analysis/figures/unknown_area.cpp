#include "analysis/figures/unknown_area.hpp"

namespace covsim {

void shade_unknown(Canvas& c, const MapView& view, const KnownCells& known, double t) {
  const double half = 0.5 * known.size;
  for (const KnownCell& k : known.cells)
    if (k.since > t || std::isinf(k.since))
      c.rectangle(view.to_px(Vec2{k.centre.x - half, k.centre.y + half}),
                  view.to_px(Vec2{k.centre.x + half, k.centre.y - half}), Marks::unknown());
}

}  // namespace covsim
