// The program route: a program that links covsim, registers Bug2, runs the planner contract
// suite on it, and runs a scenario with it through the entry point `covsim run` uses.
//   bug2_demo SCENARIO [CASES]
#include <charconv>
#include <exception>
#include <iostream>
#include <string_view>

#include "analysis/contract/planner_contract.hpp"
#include "bug2.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/coverage_run.hpp"
#include "sim/plugin.hpp"

namespace {
constexpr const char* kUsage =
    "usage: bug2_demo SCENARIO [CASES]\n"
    "  runs the planner contract suite on Bug2 (CASES random cases, default 300), then\n"
    "  SCENARIO with Bug2 as every robot's planner\n";
}  // namespace

int main(int argc, char** argv) try {
  if (argc >= 2 && (std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h")) {
    std::cout << kUsage;
    return 0;
  }
  std::uint64_t cases = 300;
  if (argc >= 3) {
    const std::string_view text = argv[2];
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), cases);
    if (ec != std::errc() || end != text.data() + text.size() || cases == 0) {
      std::cerr << "bug2_demo: CASES: expected a positive whole number, found \"" << text << "\"\n";
      return 2;
    }
  }
  if (argc < 2 || argc > 3) {
    std::cerr << kUsage;
    return 2;
  }
  covsim::registries().planners.add(example::bug2_entry());
  // The scenario first: a bad file is reported before the suite runs.
  covsim::Scenario s = covsim::load_scenario(argv[1]);
  s.coverage.planner = covsim::PlannerConfig{"bug2", {}};

  // The contract every planner that promises to reach what is reachable must keep.
  covsim::ContractSetup setup;
  setup.planner = "bug2";
  setup.range = 0.0;  // a contact sensor
  const covsim::ContractSummary c = covsim::run_contract(setup, 1, 0, cases, 2);
  std::cout << "contract: " << c.cases << " cases, " << c.reached << " reached, " << c.projected
            << " projected, " << c.stalled << " stalled, " << c.failures << " failed\n";
  for (const auto& f : c.failed)
    std::cout << "  " << f.failure << "\n  rerun: " << f.reproducer << " --plugin ...\n";

  const covsim::CoverageOutcome out = covsim::run_coverage(s);
  std::cout << "run: " << out.stop_reason << " at " << out.sim_time.seconds() << " s, cost "
            << out.cost_real << "\n";
  return c.failures == 0 && out.converged ? 0 : 1;
} catch (const covsim::ScenarioError& e) {
  std::cerr << "bug2_demo: " << e.what() << "\n";
  return 2;
} catch (const std::exception& e) {
  std::cerr << "bug2_demo: " << e.what() << "\n";
  return 1;
}
