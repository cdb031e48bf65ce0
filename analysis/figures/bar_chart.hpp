#pragma once
// A grouped bar chart (a group per category, a bar per series in it), drawn through the
// Canvas: how docs/planners.md compares planners under each coverage law.
#include <optional>
#include <string>
#include <vector>

#include "analysis/figures/canvas.hpp"

namespace covsim {

struct BarChart {
  std::string title, y_label;
  std::vector<std::string> groups, series;                 // along x; within each group
  std::vector<std::vector<std::optional<double>>> values;  // [group][series]; unset: no bar
};

std::string draw_bar_chart(const BarChart& chart, const FigureFile& file);

}  // namespace covsim
