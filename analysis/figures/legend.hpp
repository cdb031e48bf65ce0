#pragma once
// A legend: rows of a symbol and a label, laid out in as many columns as a width holds (under
// a map or a chart) or in one (beside them). Measured before the canvas exists, so a figure
// can make room for it.
#include <functional>
#include <string>
#include <vector>

#include "analysis/figures/canvas.hpp"

namespace covsim {

struct LegendEntry {
  std::string label;
  // Draws the symbol centred at a point, within about 2 × 0.7 text heights.
  std::function<void(Canvas&, Vec2)> symbol;
};

class Legend {
 public:
  Legend(std::vector<LegendEntry> entries, double font);
  bool empty() const { return entries_.empty(); }
  // One entry's width: its symbol, a gap and the widest label.
  double entry_width() const;
  double row_height() const { return 1.45 * font_; }
  // How many columns fit in `width` (at least one).
  int columns_within(double width) const;
  Vec2 size(int columns) const;
  // Entries fill the columns row by row from `top_left`.
  void draw(Canvas& c, Vec2 top_left, int columns) const;

 private:
  std::vector<LegendEntry> entries_;
  double font_;
};

}  // namespace covsim
