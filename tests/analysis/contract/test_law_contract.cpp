// The law contract suite (analysis/contract/law_contract) over every registered coverage law,
// and laws that break their contract on purpose: the harness must catch each.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/contract/law_contract.hpp"
#include "robot/coverage_law_registry.hpp"

using namespace covsim;

namespace {
constexpr std::uint64_t kLawSeed = 20261121;

std::string report(const LawContractSummary& s) {
  std::ostringstream out;
  out << s.law << ": " << s.cases << " cases, " << s.failures << " failed, worst cost rise "
      << s.worst_cost_rise << ", checks";
  for (const std::string& c : s.checks)
    out << " " << c;
  for (const LawContractResult& r : s.failed)
    out << "\n" << r.failure << "\n  rerun: " << r.reproducer;
  return out.str();
}

bool has(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// A law built from a function of (robot, knowledge, its cell's centroid), for laws made up
// by the tests.
class MadeUp final : public CoverageLaw {
 public:
  using Rule = std::function<Vec2(Vec2 generator, Vec2 centroid)>;
  MadeUp(const CellIntegrator& integrator, Rule rule) : integrator_(integrator), rule_(rule) {}
  Generators generators() const override { return Generators::positions; }
  bool moves_virtual_generators() const override { return false; }
  Vec2 target(const Robot&, const Knowledge& k) override {
    return rule_(k.points[k.self], own_cell_summary(integrator_, k).centroid);
  }

 private:
  const CellIntegrator& integrator_;
  Rule rule_;
};

// Registers a made-up law for the life of the guard.
struct Registered {
  std::string name;
  Registered(std::string n, MadeUp::Rule rule, LawContract contract) : name(std::move(n)) {
    LawEntry e;
    e.name = name;
    e.description = "made up by the law contract tests";
    e.contract = std::move(contract);
    e.make = [rule](const LawContext& ctx, const Params&) {
      return std::make_unique<MadeUp>(ctx.integrator, rule);
    };
    coverage_law_registry().add(std::move(e));
  }
  ~Registered() { coverage_law_registry().remove(name); }
  Registered(const Registered&) = delete;
  Registered& operator=(const Registered&) = delete;
};

const LawContractSummary& find(const std::vector<LawContractSummary>& all, const std::string& law) {
  const auto it = std::find_if(all.begin(), all.end(),
                               [&](const LawContractSummary& s) { return s.law == law; });
  REQUIRE(it != all.end());
  return *it;
}
}  // namespace

TEST_CASE("law contract: every registered law keeps its promises", "[contract][law]") {
  const std::vector<LawContractSummary> all = run_registry_law_contract(kLawSeed, 0, 30);
  REQUIRE(all.size() == coverage_law_registry().entries().size());
  for (const LawContractSummary& s : all) {
    INFO(report(s));
    CHECK(s.cases == 30);
    CHECK(s.failures == 0);
    const LawEntry& e = coverage_law_registry().at(s.law);
    CHECK(has(s.checks, "finite"));
    CHECK(has(s.checks, "cost") == e.contract.lloyd);
    CHECK(has(s.checks, "convex step") == bool(e.contract.convex_step_tolerance));
    if (e.contract.lloyd) CHECK(s.worst_cost_rise <= 1e-9);
  }
  // The paper's law and Lloyd on the positions promise Lloyd's step; geodesic Lloyd, in a
  // convex Ω, a damped step toward its centroid.
  CHECK(has(find(all, "virtual_generators").checks, "cost"));
  CHECK(has(find(all, "euclidean_lloyd").checks, "cost"));
  CHECK(has(find(all, "geodesic_lloyd").checks, "convex step"));
  CHECK(has(find(all, "geodesic_lloyd").checks, "at rest"));
}

TEST_CASE("law contract: a case is the same on every run", "[contract][law]") {
  const LawContractResult a = law_contract_case("geodesic_lloyd", kLawSeed, 7);
  const LawContractResult b = law_contract_case("geodesic_lloyd", kLawSeed, 7);
  CHECK(a.robots == b.robots);
  CHECK(a.robots >= 2);
  CHECK_FALSE(a.convex);  // odd cases are obstacle courses
  CHECK(a.failure.empty());
  CHECK(a.reproducer == "law_contract_case(\"geodesic_lloyd\", 20261121, 7)");
}

TEST_CASE("law contract: a law registered before the suite runs is checked too",
          "[contract][law]") {
  // Half a Lloyd step: in every Ω on the way to the centroid, at rest where it is.
  LawContract half;
  half.convex_step_tolerance = [](const Environment& env, const Params&) {
    return 1e-9 * env.diameter();
  };
  const Registered damped(
      "half_lloyd", [](Vec2 p, Vec2 c) { return p + 0.5 * (c - p); }, half);
  const std::vector<LawContractSummary> all = run_registry_law_contract(kLawSeed, 0, 20);
  const LawContractSummary& s = find(all, "half_lloyd");
  INFO(report(s));
  CHECK(s.cases == 20);
  CHECK(s.failures == 0);
  CHECK(has(s.checks, "convex step"));
  CHECK(has(s.checks, "at rest"));
}

TEST_CASE("law contract: the harness catches laws that break their promises", "[contract][law]") {
  LawContract lloyd;
  lloyd.lloyd = true;
  // Claims Lloyd's step and never moves.
  const Registered still(
      "still", [](Vec2 p, Vec2) { return p; }, lloyd);
  // Claims a damped step and overshoots the centroid.
  LawContract step;
  step.convex_step_tolerance = [](const Environment& env, const Params&) {
    return 1e-6 * env.diameter();
  };
  const Registered over(
      "overshoot", [](Vec2 p, Vec2 c) { return p + 2.5 * (c - p); }, step);
  // Promises nothing, and gives no number.
  const Registered nan(
      "nan",
      [](Vec2, Vec2) {
        return Vec2{NAN, 0.0};
      },
      LawContract{});
  for (const char* name : {"still", "overshoot", "nan"}) {
    const LawContractSummary s = run_law_contract(name, kLawSeed, 0, 10);
    INFO(report(s));
    CHECK(s.failures > 0);
    REQUIRE_FALSE(s.failed.empty());
    CHECK(s.failed.front().reproducer.find(name) != std::string::npos);
  }
  // Convex cases only for the overshoot: it promises nothing in an obstacle course.
  const LawContractSummary o = run_law_contract("overshoot", kLawSeed, 0, 10);
  for (const LawContractResult& r : o.failed)
    CHECK(r.convex);
  CHECK(run_law_contract("nan", kLawSeed, 0, 10).failures == 10);
}
