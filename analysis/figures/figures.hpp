#pragma once
// The pictures of a run, next to which the paper's Figures 3 and 4 can be put, in SVG, PDF
// or PNG through the one drawing path (Canvas).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/figures/canvas.hpp"
#include "analysis/figures/layers.hpp"
#include "analysis/records/known_cells.hpp"
#include "analysis/records/planner_map_record.hpp"
#include "analysis/records/robot_track.hpp"
#include "sim/coverage_run.hpp"
#include "sim/metrics_sample.hpp"

namespace covsim {

struct SceneOptions {
  std::string title;                                     // empty: from the scenario's name
  std::optional<std::pair<double, double>> time_window;  // [t0, t1] s; unset: the whole run
  std::vector<std::uint32_t> robots;                     // the robots drawn; empty: all
  Layers layers = Layers::all();                         // what is drawn
  // Robots that mapped Ω: the map's cells; those not yet known at the figure's time are
  // shaded (with the obstacles layer): to the robots together, or, with one robot drawn and
  // its own map kept (mapping.robot_maps), to it. Null or empty: Ω was known.
  const KnownCells* known = nullptr;
  // Planners that kept maps of their own (planner.map "sensed"): with one robot drawn, the
  // walls its planner held and the way it had ahead at the figure's time (the end of the
  // run or of the time window).
  const PlannerMapRecord* planner_maps = nullptr;
};

// Ω with its obstacles (grey), the density as a colour map with its bar, each robot's path
// in its colour from its start (hollow circle) to its end (filled, with its ID), its virtual
// generator's path (thin, dashed) and final position (square), the virtual targets
// (crosses), projected real targets (yellow crosses), the last partitions of the virtual
// generators (blue) and of the real positions (red, dashed); axes in metres, a scale bar, a
// legend and a title: each a layer that options.layers may leave out. The figure is
// file.size wide, its text file.size's font; the legend goes under the map, or beside it
// when the height is fixed (a slide). With a time window the paths are those of the window
// and the robots stand where they were at its end.
std::string scene_figure(const Scenario& scenario, const CoverageOutcome& outcome,
                         const std::vector<RobotTrack>& tracks, const SceneOptions& options,
                         const FigureFile& file);

// The cost H of the real and the virtual generators over time (in m⁴·φ), the convergence
// time marked; file.size wide (and high, or about 0.62 of its width).
std::string cost_figure(const std::vector<MetricsSample>& samples, const CoverageOutcome& outcome,
                        bool log_y, const FigureFile& file);

// A scenario's display name: its file's stem ("office" for scenarios/office.json).
std::string scenario_name(const std::string& source);

// Whether a file name in a run folder is what `covsim run` or `covsim plot` writes there: a
// record (analysis/records' is_record_file), a scene.* or cost.* figure, or replay.html. A
// new run into the folder replaces these, and keeps anything else.
bool is_run_output(const std::string& name);

}  // namespace covsim
