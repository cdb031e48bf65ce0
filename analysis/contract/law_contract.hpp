#pragma once
// The law contract suite: every coverage law against what it promises, on random
// environments. Case I of seed S is drawn from (S, I) alone: an environment (even cases a
// random convex polygon, odd ones a small obstacle course from scenarios/obstacle_course)
// and 2 to 8 generators (in Ω; the paper's virtual generators also outside it). Each robot's
// target is taken from the shared partition (the ideal network) and from its own cell (a
// networked robot that heard everybody), and from a random part of the others (one that
// heard only some). Every law, autonomous or not:
//
// - every target is finite, from whatever it knows;
// - a robot computing its own cell gets the target the shared partition gives (within
//   1e-9 of Ω's diameter).
//
// What else a law promises is declared in its registry entry (LawEntry::contract):
//
// - lloyd: the target is the centroid of the robot's cell ∩ Ω (from a partition the suite
//   computes itself), a step of every robot to its target does not raise the cost H (a
//   relative 1e-9 allowed for rounding), and at a centroidal configuration (found by Lloyd
//   iterations of the suite's own) every target stays on its generator;
// - convex_step_tolerance: in a convex Ω the target lies within that tolerance of the segment
//   from the generator to its cell's centroid, so at a centroidal configuration it stays
//   within the tolerance of the generator.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "robot/coverage_law.hpp"

namespace covsim {

struct LawContractResult {
  std::uint64_t seed = 0, index = 0;
  bool convex = false;
  std::size_t robots = 0;
  std::string failure;  // empty when every check passed
  // "law_contract_case(LAW, S, I)": reruns this case alone.
  std::string reproducer;
};

struct LawContractSummary {
  std::string law;
  std::size_t cases = 0, failures = 0;
  // What was checked, by name: "finite", "own cell", "centroid", "cost", "at rest",
  // "convex step".
  std::vector<std::string> checks;
  double worst_cost_rise = 0.0;  // H after a step / H before - 1, over the Lloyd laws' cases
  std::vector<LawContractResult> failed;  // the first few failures
};

// Case `index` of `seed` for the registered law `law`, with its default parameters.
LawContractResult law_contract_case(const std::string& law, std::uint64_t seed,
                                    std::uint64_t index);
// Cases first, ..., first + count - 1 for one registered law.
LawContractSummary run_law_contract(const std::string& law, std::uint64_t seed, std::uint64_t first,
                                    std::uint64_t count);
// Every entry of coverage_law_registry() as it stands (a plugin's or a program's laws
// included, if registered first), in registry order, on the same cases.
std::vector<LawContractSummary> run_registry_law_contract(std::uint64_t seed, std::uint64_t first,
                                                          std::uint64_t count);

}  // namespace covsim
