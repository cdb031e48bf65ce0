#pragma once
// The contract suites' one check: `cases` cases of `seed` for a setup, none failing, with a
// report of the summary and of each failure's reproducer when one does.
#include <catch2/catch.hpp>

#include <sstream>

#include "analysis/contract/planner_contract.hpp"

namespace covsim::test {

inline ContractSummary check_contract(const ContractSetup& setup, std::uint64_t seed,
                                      std::uint64_t cases) {
  const ContractSummary s = run_contract(setup, seed, 0, cases, 1);
  std::ostringstream report;
  report << setup.label() << ": " << s.cases << " cases, " << s.reached << " reached, "
         << s.projected << " projected, " << s.stalled << " stalled, worst path/L* "
         << s.worst_ratio << ", worst path/bound " << s.worst_bound_use;
  for (const ContractResult& r : s.failed)
    report << "\n" << r.failure << "\n  rerun: " << r.reproducer;
  INFO(report.str());
  CHECK(s.cases == cases);
  CHECK(s.failures == 0);
  return s;
}

}  // namespace covsim::test
