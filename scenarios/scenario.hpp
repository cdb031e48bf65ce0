#pragma once
// A scenario as read from its JSON file and validated: the environment Ω, the density φ,
// the robots' start positions and the seed. See docs/scenario-format.md for every key.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/density.hpp"
#include "geometry/environment.hpp"
#include "robot/coverage_config.hpp"
#include "scenarios/recording_config.hpp"
#include "scenarios/robot_draw.hpp"
#include "scenarios/run_limits.hpp"

namespace covsim {

struct Scenario {
  std::string source;              // the file it came from, for messages
  nlohmann::json json;             // as read, so that a trace can embed it
  std::filesystem::path base_dir;  // files it names (rasters) are relative to this
  std::shared_ptr<const Environment> environment;
  std::shared_ptr<const Density> density;
  // Given, or drawn from the seed ("count" and "start", "jitter"); empty when the file has
  // no "robots".
  std::vector<Vec2> robot_positions;
  RobotDraw draw;  // how they were drawn (separation, jitter)
  std::optional<std::uint64_t> seed;
  CoverageConfig coverage;  // the controller's settings, defaults where the file is silent
  RecordingConfig recording;
  RunLimits limits;
};

// Throws ScenarioError naming the file, the JSON path and what was expected: malformed
// JSON, unknown keys, wrong types, invalid polygons, a robot outside Ω or two robots at the
// same place, a density with no mass on Ω.
Scenario load_scenario(const std::filesystem::path& file);
// The scenario with another seed: read again, so that what it draws from its seed (robot
// starts, density means) is drawn from the new one.
Scenario with_seed(const Scenario& scenario, std::uint64_t seed);
// Whether a scenario draws anything from its seed besides the run's own randomness.
bool draws_from_seed(const nlohmann::json& scenario);
// The same from JSON already parsed; files it names (rasters) are relative to base_dir.
Scenario parse_scenario(const nlohmann::json& json, const std::string& source,
                        const std::filesystem::path& base_dir);

}  // namespace covsim
