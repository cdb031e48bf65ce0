#include "analysis/figures/legend.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/figures/marks.hpp"

namespace covsim {

namespace {
constexpr double kSymbol = 2.0, kGap = 0.45, kColumnGap = 1.0;  // in text heights
}  // namespace

Legend::Legend(std::vector<LegendEntry> entries, double font)
    : entries_(std::move(entries)), font_(font) {}

double Legend::entry_width() const {
  double widest = 0;
  for (const LegendEntry& e : entries_)
    widest = std::max(widest, text_width(e.label, font_));
  return (kSymbol + kGap) * font_ + widest;
}

int Legend::columns_within(double width) const {
  const double column = entry_width() + kColumnGap * font_;
  const int n = static_cast<int>(std::floor((width + kColumnGap * font_) / column));
  return std::clamp(n, 1, std::max(1, static_cast<int>(entries_.size())));
}

Vec2 Legend::size(int columns) const {
  if (entries_.empty()) return {0, 0};
  const int rows = static_cast<int>((entries_.size() + columns - 1) / columns);
  return {columns * entry_width() + (columns - 1) * kColumnGap * font_, rows * row_height()};
}

void Legend::draw(Canvas& c, Vec2 top_left, int columns) const {
  const double column = entry_width() + kColumnGap * font_;
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    const double x = top_left.x + column * static_cast<double>(k % columns);
    const double y = top_left.y + row_height() * static_cast<double>(k / columns);
    const double mid = y + 0.5 * row_height();
    entries_[k].symbol(c, {x + 0.5 * kSymbol * font_, mid});
    // The label's x-height centred on the symbol.
    c.text({x + (kSymbol + kGap) * font_, mid + 0.36 * font_}, entries_[k].label, font_,
           Marks::ink());
  }
}

}  // namespace covsim
