#pragma once
// What the controller tests share: the paper's scenario files, and an observer that checks
// every motion step against Ω.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "scenarios/scenario.hpp"
#include "sim/coverage_run.hpp"

namespace covsim::test {

inline Scenario paper(const std::string& name) {
  return load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/" + name);
}

// A scenario given as JSON, its files looked up beside the shipped scenarios.
inline Scenario parse_beside_paper(const nlohmann::json& j, const std::string& name) {
  return parse_scenario(j, name, std::filesystem::path(COVSIM_SOURCE_DIR) / "scenarios");
}

// Counts motion steps and those that leave Ω, and keeps the largest gap between a robot
// and its virtual generator.
struct MotionChecker final : CoverageObserver {
  std::shared_ptr<const Environment> env;  // shared: the scenario may be a temporary
  std::map<std::uint32_t, Vec2> last;
  std::size_t steps = 0, outside = 0;
  double max_real_virtual_gap = 0.0;
  explicit MotionChecker(const Scenario& s) : env(s.environment) {
    for (std::uint32_t i = 0; i < s.robot_positions.size(); ++i)
      last[i] = s.robot_positions[i];
  }
  void on_motion(SimTime, const Robot& r) override {
    ++steps;
    if (!env->segment_inside(last[r.id], r.position)) ++outside;
    last[r.id] = r.position;
    max_real_virtual_gap =
        std::max(max_real_virtual_gap, distance(r.position, r.virtual_generator));
  }
};

}  // namespace covsim::test
