// `covsim planner-contract --planner NAME [--range R] [--noise S] [--family F] [--cases N]
// [--seed N] [--jobs J]`: runs the planner contract suite (analysis/contract/planner_contract) for
// a soak, `--case I` for one case in detail, or `--ranges 0,0.5,2,inf` for the range effect (the
// same cases at each range). Prints a summary and one reproducer line per failing case; exit 1 if
// any case failed.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "analysis/contract/planner_contract.hpp"
#include "apps/commands.hpp"
#include "apps/input_error.hpp"
#include "apps/plugin_loader.hpp"
#include "io/atomic_file.hpp"
#include "planners/planner_registry.hpp"

namespace covsim::app {

namespace {
struct Options {
  ContractSetup setup;
  std::string range = "inf";
  std::string family = "courses";
  std::string ranges;  // the range curve's ranges, comma-separated
  bool incomplete = false;
  std::uint64_t seed = 1, first = 0, cases = 1000;
  std::optional<std::uint64_t> one;
  std::string out;
  std::vector<std::string> plugins;
  unsigned jobs = 1;
};

double parse_range(const std::string& s) {
  if (s == "inf" || s == "infinite") return INFINITY;
  std::size_t used = 0;
  double v = -1.0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || !(v >= 0.0) || !std::isfinite(v))
    throw InputError("planner-contract: --range: expected a number >= 0 or \"inf\", got \"" + s +
                     "\"");
  return v;
}

std::string number(double v) {
  return std::isinf(v) ? "inf" : fmt::format("{}", v);
}

nlohmann::ordered_json points(const std::vector<Vec2>& ps) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (Vec2 p : ps)
    a.push_back({p.x, p.y});
  return a;
}

void write_case(const ContractResult& r, const std::string& path) {
  nlohmann::ordered_json j;
  j["rings"] = nlohmann::ordered_json::array();
  for (const auto& ring : r.rings)
    j["rings"].push_back(points(ring));
  j["start"] = {r.start.x, r.start.y};
  j["goal"] = {r.goal.x, r.goal.y};
  j["status"] = std::string(to_string(r.status));
  j["path"] = points(r.path);
  j["modes"] = r.modes;
  AtomicFile f(path);
  f.stream() << j.dump(1) << '\n';
  f.commit();
}

void print_case(const ContractResult& r) {
  std::cout << fmt::format(
      "case {}: start ({}, {}) goal ({}, {}) {}: {} at ({}, {}) after {} steps, path {:.6g} m, "
      "L* {:.6g} m, bound {:.6g} m, {} boundary-following episodes\n",
      r.index, r.start.x, r.start.y, r.goal.x, r.goal.y, r.reachable ? "reachable" : "outside Ω",
      to_string(r.status), r.end.x, r.end.y, r.steps, r.length, r.shortest, r.bound, r.episodes);
  if (!r.failure.empty()) std::cout << "FAILED: " << r.failure << '\n';
}
}  // namespace

void add_planner_contract_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("planner-contract",
                                     "Run the planner contract suite on random obstacle courses");
  cmd->add_option("--planner", o->setup.planner, "Planner name")->capture_default_str();
  cmd->add_option("--range", o->range, "Sensor range [m], or inf")->capture_default_str();
  cmd->add_option("--noise", o->setup.noise_sigma, "Range noise sigma [m]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--step", o->setup.step, "Step length [m]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--radius", o->setup.radius,
                  "Robot radius [m]: the planner works in the course shrunk by it (courses only)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--resolution", o->setup.resolution,
                  "Cell side of grid_astar's grid, or of a sensed map [m]")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--map", o->setup.map,
                  "What a map planner plans on: given (Ω) or sensed (the walls its readings "
                  "showed, unseen space free)")
      ->check(CLI::IsMember({"given", "sensed"}))
      ->capture_default_str();
  cmd->add_flag("--incomplete", o->incomplete,
                "Check only that the planner stays in Ω, ends, and reports stalls honestly, "
                "even if its registry entry promises to reach reachable goals");
  cmd->add_option("--family", o->family, "Cases: courses (random obstacle courses) or combs")
      ->check(CLI::IsMember({"courses", "combs"}))
      ->capture_default_str();
  cmd->add_option("--ranges", o->ranges,
                  "Comma-separated ranges (one of them 0): mean path/L* and path over the "
                  "contact sensor's path at each, on the same cases");
  cmd->add_option("--seed", o->seed, "Seed of the suite")->capture_default_str();
  cmd->add_option("--first", o->first, "First case index")->capture_default_str();
  cmd->add_option("--cases", o->cases, "Number of cases")->capture_default_str();
  cmd->add_option("--case", o->one, "Run this one case and describe it");
  cmd->add_option("--out", o->out,
                  "With --case: write the map, the path and the planner's modes as JSON");
  cmd->add_option("--jobs", o->jobs, "Worker threads")
      ->check(CLI::Range(1u, 256u))
      ->capture_default_str();
  add_plugin_option(cmd, o->plugins);
  cmd->callback([o] {
    load_plugins(o->plugins);
    if (planner_registry().find(o->setup.planner) == nullptr) {
      throw InputError(
          fmt::format("planner-contract: --planner: unknown planner \"{}\" (registered: {})",
                      o->setup.planner, fmt::join(planner_registry().names(), ", ")));
    }
    if (const std::optional<std::string> why = contract_refusal(o->setup.planner)) {
      throw InputError(
          fmt::format("planner-contract: --planner: planner \"{}\" {}", o->setup.planner, *why));
    }
    if (o->setup.map != "given" &&
        find_param(planner_registry().at(o->setup.planner).params, "map") == nullptr)
      throw InputError(fmt::format(
          "planner-contract: --map: planner \"{}\" offers no choice of map (it plans on what "
          "it senses, or on nothing)",
          o->setup.planner));
    o->setup.range = parse_range(o->range);
    o->setup.family = o->family == "combs" ? CaseFamily::combs : CaseFamily::courses;
    if (o->setup.radius > 0.0 && o->setup.family == CaseFamily::combs)
      throw InputError("planner-contract: --radius: applies to --family courses, not combs");
    if (o->incomplete) o->setup.complete = false;
    if (!o->ranges.empty()) {
      std::vector<double> ranges;
      std::size_t at = 0;
      while (at <= o->ranges.size()) {
        const std::size_t comma = std::min(o->ranges.find(',', at), o->ranges.size());
        ranges.push_back(parse_range(o->ranges.substr(at, comma - at)));
        at = comma + 1;
      }
      if (std::find(ranges.begin(), ranges.end(), 0.0) == ranges.end())
        throw InputError("planner-contract: --ranges: must hold 0 (the contact sensor)");
      const RangeCurve curve = range_curve(o->setup, ranges, o->seed, o->first, o->cases, o->jobs);
      std::cout << fmt::format("{} {}: {} cases reached at every range\n", o->setup.planner,
                               to_string(o->setup.family), curve.cases);
      std::cout << "range  path/L* mean  path/contact mean  worst  failed\n";
      std::size_t failures = 0;
      for (const RangePoint& p : curve.points) {
        std::cout << fmt::format("{:<5}  {:12.4f}  {:17.4f}  {:5.3f}  {}\n", number(p.range),
                                 p.mean_ratio, p.mean_vs_contact, p.worst_vs_contact, p.failures);
        failures += p.failures;
      }
      if (failures > 0) throw std::runtime_error(fmt::format("{} cases failed", failures));
      return;
    }
    if (o->one) {
      const ContractResult r = run_contract_case(o->setup, o->seed, *o->one);
      print_case(r);
      if (!o->out.empty()) write_case(r, o->out);
      if (!r.failure.empty()) throw std::runtime_error("the case failed its contract");
      return;
    }
    const ContractSummary s = run_contract(o->setup, o->seed, o->first, o->cases, o->jobs);
    std::cout << fmt::format(
        "{}: {} cases ({} reachable): {} reached, {} projected, {} stalled; {} failed; "
        "path/L* mean {:.4f}, worst {:.4f} (case {}); worst path/bound {:.4f}; {} recoveries; {} "
        "reversing ({} early)\n",
        o->setup.label(), s.cases, s.reachable, s.reached, s.projected, s.stalled, s.failures,
        s.mean_ratio, s.worst_ratio, s.worst_ratio_case, s.worst_bound_use, s.recoveries,
        s.reversing, s.early_reversing);
    for (const ContractResult& r : s.failed)
      std::cout << "FAILED: " << r.failure << "\n  rerun: " << r.reproducer << '\n';
    if (s.failures > 0) throw std::runtime_error(fmt::format("{} cases failed", s.failures));
  });
}

}  // namespace covsim::app
