// `covsim cells SCENARIO --generators FILE`: mass, centroid and cost of each generator's
// Voronoi cell in the scenario's environment, as JSON on stdout.
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "geometry/geometry_error.hpp"
#include "geometry/voronoi_partition.hpp"
#include "io/interrupt.hpp"
#include "scenarios/input_file.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim::app {

void add_cells_command(CLI::App& app) {
  struct Options {
    std::string scenario;
    std::string generators;
  };
  auto opts = std::make_shared<Options>();
  CLI::App* cmd =
      app.add_subcommand("cells", "Mass, centroid and cost of each generator's Voronoi cell in Ω");
  cmd->add_option("SCENARIO", opts->scenario,
                  "Scenario file (its environment and density are used)")
      ->required();
  cmd->add_option("--generators", opts->generators,
                  "JSON or YAML file holding an array [[x, y], ...]")
      ->required();
  cmd->callback([opts] {
    const Scenario scenario = load_scenario(opts->scenario);
    const InputFile in = read_input(opts->generators);
    const JsonValue list(in.json, in.source);
    const CellIntegrator integrator(*scenario.environment, *scenario.density);
    std::unique_ptr<VoronoiPartition> partition;
    try {
      std::vector<Vec2> generators = list.points();
      try {
        partition = std::make_unique<VoronoiPartition>(integrator, std::move(generators));
      } catch (const GeometryError& e) {
        list.fail(e.what());
      }
    } catch (const ScenarioError& e) {
      throw in.located(e);
    }
    nlohmann::ordered_json out;
    out["cells"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < partition->size(); ++i) {
      // Hundreds of thousands of cells take seconds: SIGINT and SIGTERM stop between cells.
      if (i % 1024 == 0)
        if (const int signal = pending_interrupt()) throw Interrupted(signal);
      const CellSummary s = partition->summary(i);
      nlohmann::ordered_json cell;
      cell["mass"] = s.mass;
      cell["centroid"] = {s.centroid.x, s.centroid.y};
      cell["cost"] = s.cost;
      out["cells"].push_back(std::move(cell));
    }
    out["total_cost"] = partition->cost();
    std::cout << out.dump() << '\n';
  });
}

}  // namespace covsim::app
