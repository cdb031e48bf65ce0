#include "analysis/sweep/sweep_tables.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "analysis/records/result_fields.hpp"
#include "analysis/sweep/statistics.hpp"
#include "io/atomic_file.hpp"

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

void write_runs_csv(const fs::path& file, const SweepSpec& spec,
                    const std::vector<SweepResult>& results) {
  const std::vector<SweepRun> runs = spec.runs();
  AtomicFile f(file);
  std::string out = "run,setting";
  for (const std::string& p : spec.parameters)
    out += "," + csv_quote(p);
  out += ",seed";
  for (const auto& field : run_fields())
    out += "," + field.name;
  out += ",error\n";
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
}

void write_summary_csv(const fs::path& file, const SweepSpec& spec,
                       const std::vector<SweepResult>& results) {
  const std::vector<SweepRun> runs = spec.runs();
  std::map<std::size_t, std::vector<const SweepResult*>> by_setting;
  for (const SweepResult& r : results)
    by_setting[runs.at(r.index).setting].push_back(&r);
  AtomicFile f(file);
  std::string out = "setting";
  for (const std::string& p : spec.parameters)
    out += "," + csv_quote(p);
  out += ",runs,failed,converged_rate";
  for (const std::string& m : sweep_metrics())
    out += fmt::format(
        ",{0}_mean,{0}_std,{0}_ci95,{0}_median,{0}_q1,{0}_q3,{0}_modes,{0}_low_fraction,"
        "{0}_low_median,{0}_high_median",
        m);
  out += "\n";
  for (const auto& [setting, rs] : by_setting) {
    out += fmt::format("{}", setting);
    for (const auto& v : spec.settings[setting])
      out += "," + csv_quote(csv_value(v));
    std::size_t ok = 0, converged = 0;
    for (const SweepResult* r : rs) {
      ok += r->error ? 0 : 1;
      converged += (!r->error && r->converged()) ? 1 : 0;
    }
    // What a sample cannot tell is left empty, never written as 0: a rate without runs, a
    // mean without values, a spread from fewer than two.
    out += fmt::format(",{},{},{}", rs.size(), rs.size() - ok,
                       ok > 0 ? fmt::format("{}", static_cast<double>(converged) / ok) : "");
    for (const std::string& m : sweep_metrics()) {
      std::vector<double> xs;
      for (const SweepResult* r : rs) {
        // A measure a run did not take (null: λ2 above metrics.algebraic_connectivity_robots)
        // is no sample.
        const double x = r->error ? NAN : r->number(m);
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
}

}  // namespace covsim
