// The program route: a program that links covsim, registers the damped Lloyd law and runs
// a sweep over its gain through the entry point `covsim sweep` uses.
//   damped_lloyd_demo SCENARIO OUT_DIR
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string_view>

#include "analysis/sweep/sweep_runner.hpp"
#include "damped_lloyd.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/plugin.hpp"

namespace {
constexpr const char* kUsage =
    "usage: damped_lloyd_demo SCENARIO OUT_DIR\n"
    "  sweeps the damped Lloyd law's gain (0.3 and 1) on SCENARIO into OUT_DIR\n";
}  // namespace

int main(int argc, char** argv) try {
  if (argc >= 2 && (std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h")) {
    std::cout << kUsage;
    return 0;
  }
  if (argc != 3) {
    std::cerr << kUsage;
    return 2;
  }
  covsim::registries().laws.add(example::damped_lloyd_entry());
  const std::filesystem::path out = argv[2];
  std::filesystem::create_directories(out);
  {
    std::ofstream f(out / "sweep.in.json");
    f << nlohmann::json{
        {"scenario", std::filesystem::absolute(argv[1]).string()},
        {"grid", {{"controller.type", {"damped_lloyd"}}, {"controller.gain", {0.3, 1.0}}}},
        {"seeds", {1}}};
  }
  const covsim::SweepSpec spec = covsim::load_sweep(out / "sweep.in.json");
  const auto results = covsim::run_sweep(spec, out / "sweep", covsim::SweepOptions{2, false, 0, 1});
  covsim::write_runs_csv(out / "runs.csv", spec, results);
  bool ok = true;
  for (const auto& r : results) {
    std::cout << "run " << r.index << ": " << (r.error ? *r.error : r.values.dump()) << "\n";
    ok = ok && !r.error && r.converged();
  }
  return ok ? 0 : 1;
} catch (const covsim::ScenarioError& e) {
  std::cerr << "damped_lloyd_demo: " << e.what() << "\n";
  return 2;
} catch (const std::exception& e) {
  std::cerr << "damped_lloyd_demo: " << e.what() << "\n";
  return 1;
}
