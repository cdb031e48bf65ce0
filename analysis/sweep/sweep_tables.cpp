#include "analysis/sweep/sweep_tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "analysis/records/csv_metadata.hpp"
#include "analysis/records/result_fields.hpp"
#include "analysis/sweep/statistics.hpp"
#include "io/atomic_file.hpp"
#include "scenarios/scenario_description.hpp"

namespace covsim {

namespace fs = std::filesystem;

std::vector<std::string> sweep_metrics() {
  std::vector<std::string> m;
  for (const auto& f : run_fields()) {
    if (f.summarized) m.push_back(f.name);
  }
  return m;
}

std::string csv_value(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_null()) return "null";
  return v.dump();
}

std::vector<const SweepResult*> distinct_runs(const std::vector<const SweepResult*>& runs) {
  std::vector<const SweepResult*> out;
  std::set<std::string> seen;
  for (const SweepResult* r : runs) {
    if (r->error) continue;
    const std::string f = r->fingerprint();
    // A run without a fingerprint cannot be told from another: it counts.
    if (f.empty() || seen.insert(f).second) out.push_back(r);
  }
  return out;
}

namespace {
// Each setting's results, in the order of their indices.
std::map<std::size_t, std::vector<const SweepResult*>> by_setting(
    const SweepSpec& spec, const std::vector<SweepResult>& results) {
  const std::vector<SweepRun> runs = spec.runs();
  std::map<std::size_t, std::vector<const SweepResult*>> out;
  for (const SweepResult& r : results)
    out[runs.at(r.index).setting].push_back(&r);
  for (auto& [setting, rs] : out)
    std::sort(rs.begin(), rs.end(),
              [](const SweepResult* a, const SweepResult* b) { return a->index < b->index; });
  return out;
}
}  // namespace

std::vector<std::string> identical_seed_warnings(const SweepSpec& spec,
                                                 const std::vector<SweepResult>& results,
                                                 std::size_t shown) {
  const std::vector<SweepRun> runs = spec.runs();
  std::vector<std::string> out;
  std::size_t more = 0;
  for (const auto& [setting, rs] : by_setting(spec, results)) {
    std::size_t ok = 0;
    for (const SweepResult* r : rs)
      ok += r->error ? 0 : 1;
    const std::size_t distinct = distinct_runs(rs).size();
    if (distinct == ok) continue;
    if (out.size() == shown) {
      ++more;
      continue;
    }
    std::string label;
    for (std::size_t p = 0; p < spec.parameters.size(); ++p)
      label += fmt::format("{}{}={}", p == 0 ? ", " : " ", spec.parameters[p],
                           csv_value(spec.settings[setting][p]));
    // The seeds that repeated an earlier seed's run.
    std::map<std::string, std::uint64_t> first;
    std::string repeats;
    for (const SweepResult* r : rs) {
      if (r->error || r->fingerprint().empty()) continue;
      const std::uint64_t seed = runs.at(r->index).seed;
      const auto [it, fresh] = first.emplace(r->fingerprint(), seed);
      if (!fresh)
        repeats +=
            fmt::format("{}seed {} = seed {}", repeats.empty() ? "" : ", ", seed, it->second);
    }
    out.push_back(fmt::format(
        "setting {}{}: {} distinct run{} of {} ({}: the same fingerprint); its statistics "
        "count the distinct runs. Seeds change a run only through what is drawn: robots.count "
        "with robots.start, robots.jitter, or a random model (docs/sweeps.md)",
        setting, label, distinct, distinct == 1 ? "" : "s", ok, repeats));
  }
  if (more > 0)
    out.push_back(fmt::format(
        "{} more settings with identical runs (summary.csv's distinct_runs column)", more));
  return out;
}

namespace {
// The swept parameters, each with its unit in the scenario.
void add_parameters(const SweepSpec& spec, std::vector<CsvColumn>& out) {
  for (const std::string& p : spec.parameters)
    out.push_back(CsvColumn{p, FieldKind::json, scenario_key_unit(p),
                            "swept: the value of this dotted path of the scenario"});
}
}  // namespace

std::vector<CsvColumn> runs_columns(const SweepSpec& spec) {
  std::vector<CsvColumn> out{{"run", FieldKind::integer, "", "the run's index in the sweep"},
                             {"setting", FieldKind::integer, "", "the setting's index"}};
  add_parameters(spec, out);
  out.push_back({"seed", FieldKind::integer, "", "the run's seed"});
  for (const auto& f : run_fields())
    out.push_back({f.name, f.kind, f.unit, f.description});
  out.push_back({"error", FieldKind::text, "", "why the run failed; empty if it did not"});
  return out;
}

std::vector<CsvColumn> summary_columns(const SweepSpec& spec) {
  std::vector<CsvColumn> out{{"setting", FieldKind::integer, "", "the setting's index"}};
  add_parameters(spec, out);
  out.push_back({"runs", FieldKind::integer, "", "runs of the setting"});
  out.push_back({"failed", FieldKind::integer, "", "runs that failed"});
  out.push_back({"distinct_runs", FieldKind::integer, "",
                 "runs that did not fail, runs with one fingerprint counted once: the statistics' "
                 "sample"});
  out.push_back({"converged_rate", FieldKind::number, "",
                 "the share of the distinct runs that "
                 "converged"});
  for (const auto& f : run_fields()) {
    if (!f.summarized) continue;
    const auto add = [&](const char* suffix, const std::string& unit, const std::string& what) {
      out.push_back({f.name + suffix, FieldKind::number, unit, what + " of " + f.name});
    };
    add("_mean", f.unit, "the mean");
    add("_std", f.unit, "the sample standard deviation");
    add("_ci95", f.unit, "the half-width of the 95% confidence interval of the mean");
    add("_median", f.unit, "the median");
    add("_q1", f.unit, "the first quartile");
    add("_q3", f.unit, "the third quartile");
    add("_modes", "", "the number of modes (1 or 2)");
    add("_low_fraction", "", "with two modes, the share of runs in the lower");
    add("_low_median", f.unit, "with two modes, the median of the lower");
    add("_high_median", f.unit, "with two modes, the median of the higher");
  }
  return out;
}

void write_runs_csv(const fs::path& file, const SweepSpec& spec,
                    const std::vector<SweepResult>& results) {
  const std::vector<SweepRun> runs = spec.runs();
  const std::vector<CsvColumn> columns = runs_columns(spec);
  AtomicFile f(file);
  std::string out = csv_header(columns) + "\n";
  for (const SweepResult& r : results) {
    const SweepRun& run = runs.at(r.index);
    out += fmt::format("{},{}", r.index, run.setting);
    for (const auto& v : run.values)
      out += "," + csv_quote(csv_value(v));
    out += fmt::format(",{}", run.seed);
    for (const auto& field : run_fields()) {
      const auto it = r.values.find(field.name);
      out += "," + (it == r.values.end() ? std::string() : csv_cell(*it));
    }
    out += "," + csv_quote(r.error.value_or("")) + "\n";
  }
  f.stream() << out;
  f.commit();
  write_csv_metadata(file, "covsim sweep: one row per run", columns);
}

void write_summary_csv(const fs::path& file, const SweepSpec& spec,
                       const std::vector<SweepResult>& results) {
  const std::vector<CsvColumn> columns = summary_columns(spec);
  AtomicFile f(file);
  std::string out = csv_header(columns) + "\n";
  for (const auto& [setting, all] : by_setting(spec, results)) {
    out += fmt::format("{}", setting);
    for (const auto& v : spec.settings[setting])
      out += "," + csv_quote(csv_value(v));
    std::size_t failed = 0, converged = 0;
    for (const SweepResult* r : all)
      failed += r->error ? 1 : 0;
    const std::vector<const SweepResult*> rs = distinct_runs(all);
    for (const SweepResult* r : rs)
      converged += r->converged() ? 1 : 0;
    // What a sample cannot tell is left empty, never written as 0: a rate without runs, a
    // mean without values, a spread from fewer than two.
    out += fmt::format(
        ",{},{},{},{}", all.size(), failed, rs.size(),
        rs.empty() ? "" : fmt::format("{}", static_cast<double>(converged) / rs.size()));
    for (const std::string& m : sweep_metrics()) {
      std::vector<double> xs;
      for (const SweepResult* r : rs) {
        // A measure a run did not take (null: λ2 above metrics.algebraic_connectivity_robots)
        // is no sample.
        const double x = r->number(m);
        if (!std::isnan(x)) xs.push_back(x);
      }
      const SampleSummary s = summarize_sample(xs);
      out += s.n == 0   ? ",,,"
             : s.n == 1 ? fmt::format(",{},,", s.mean)
                        : fmt::format(",{},{},{}", s.mean, s.stddev, s.ci95);
      out += s.n == 0 ? ",,," : fmt::format(",{},{},{}", s.median, s.q1, s.q3);
      // Modes need a sample to split: at least kModesMinSample runs (analysis/sweep/statistics).
      const Modes modes = split_modes(xs);
      out += s.n < kModesMinSample ? ",,,,"
             : modes.bimodal ? fmt::format(",2,{},{},{}", modes.low_fraction, modes.low_median,
                                           modes.high_median)
                             : ",1,,,";
    }
    out += "\n";
  }
  f.stream() << out;
  f.commit();
  write_csv_metadata(file, "covsim sweep: one row per setting", columns);
}

}  // namespace covsim
