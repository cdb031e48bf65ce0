// The program route: a program that links covsim, registers Bug2, runs the planner contract
// suite on it, and runs a scenario with it through the entry point `covsim run` uses.
//   bug2_demo SCENARIO [CASES]
#include <cstdlib>
#include <iostream>

#include "analysis/contract/planner_contract.hpp"
#include "bug2.hpp"
#include "scenarios/scenario.hpp"
#include "sim/coverage_run.hpp"
#include "sim/plugin.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: bug2_demo SCENARIO [CASES]\n";
    return 2;
  }
  covsim::registries().planners.add(example::bug2_entry());

  // The contract every planner that promises to reach what is reachable must keep.
  covsim::ContractSetup setup;
  setup.planner = "bug2";
  setup.range = 0.0;  // a contact sensor
  const std::uint64_t cases = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 300;
  const covsim::ContractSummary c = covsim::run_contract(setup, 1, 0, cases, 2);
  std::cout << "contract: " << c.cases << " cases, " << c.reached << " reached, " << c.projected
            << " projected, " << c.stalled << " stalled, " << c.failures << " failed\n";
  for (const auto& f : c.failed)
    std::cout << "  " << f.failure << "\n  rerun: " << f.reproducer << " --plugin ...\n";

  covsim::Scenario s = covsim::load_scenario(argv[1]);
  s.coverage.planner = covsim::PlannerConfig{"bug2", {}};
  const covsim::CoverageOutcome out = covsim::run_coverage(s);
  std::cout << "run: " << out.stop_reason << " at " << out.sim_time.seconds() << " s, cost "
            << out.cost_real << "\n";
  return c.failures == 0 && out.converged ? 0 : 1;
}
