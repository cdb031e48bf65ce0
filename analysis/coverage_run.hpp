#pragma once
// One run of the paper's controller on a scenario, from start to convergence (or the time
// limit), and what it ends with: the final positions, the three costs of the paper's
// Remark 1, and the fingerprint.
#include <cstdint>
#include <string>
#include <vector>

#include "robot/coverage_controller.hpp"
#include "scenarios/scenario.hpp"

namespace covsim {

class TraceSink;

struct RobotOutcome {
  Vec2 position, virtual_generator, virtual_target, real_target;
  bool projected = false;
  PlanStatus status = PlanStatus::reached;
  double path_length = 0.0;
};

struct CoverageOutcome {
  bool converged = false;
  SimTime sim_time;
  std::string stop_reason;  // "converged" or "max_time"
  std::uint64_t events = 0;
  std::uint64_t seed = 0;
  std::uint64_t fingerprint = 0;
  std::vector<RobotOutcome> robots;
  // Remark 1: H of the virtual generators on their partition, of the real positions on
  // theirs (the last partition), and of the real positions on the virtual partition.
  double cost_virtual = 0.0, cost_real = 0.0, cost_real_in_virtual_partition = 0.0;
  bool decentralized = false;  // false: the ideal network, every robot knows every state
  NetworkTotals network;
};

// Throws ScenarioError if the scenario has no robots or no seed.
CoverageOutcome run_coverage(const Scenario& scenario, CoverageObserver* observer = nullptr,
                             TraceSink* trace = nullptr);

}  // namespace covsim
