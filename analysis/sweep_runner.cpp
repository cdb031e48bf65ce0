#include "analysis/sweep_runner.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "analysis/coverage_run.hpp"
#include "analysis/line_chart.hpp"
#include "analysis/provenance.hpp"
#include "analysis/result_fields.hpp"
#include "analysis/statistics.hpp"
#include "core/atomic_file.hpp"
#include "core/fingerprint.hpp"
#include "core/interrupt.hpp"
#include "scenarios/scenario_description.hpp"

namespace covsim {

namespace fs = std::filesystem;

namespace {

nlohmann::ordered_json to_json(const SweepResult& r) {
  nlohmann::ordered_json j{{"index", r.index}};
  for (const auto& [key, value] : r.values.items())
    j[key] = value;
  if (r.error) j["error"] = *r.error;
  return j;
}

std::optional<SweepResult> from_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    SweepResult r;
    r.index = j.at("index").get<std::size_t>();
    if (j.contains("error")) r.error = j.at("error").get<std::string>();
    for (const auto& f : run_fields()) {
      if (j.contains(f.name)) {
        r.values[f.name] = j.at(f.name);
      } else if (!r.error) {
        return std::nullopt;  // a damaged or older result is run again
      }
    }
    return r;
  } catch (const std::exception&) {
    return std::nullopt;  // a damaged result is run again
  }
}

// One run, sampled for its communication measures; with keep_series its samples are kept as
// DIR/runs/<index>.metrics.csv.
SweepResult execute(const SweepSpec& spec, const SweepRun& run, const fs::path& dir,
                    bool keep_series) {
  SweepResult r;
  r.index = run.index;
  const auto start = std::chrono::steady_clock::now();
  RunMeasures m;
  try {
    const Scenario s =
        parse_scenario(spec.scenario_for(run), fmt::format("{} (run {})", spec.source, run.index),
                       spec.scenario_dir);
    MetricsSampler sampler;
    m.outcome = run_coverage(s, &sampler);
    m.communication = summarize_communication(sampler.samples());
    if (keep_series) {
      AtomicFile series(dir / "runs" / fmt::format("{}.metrics.csv", run.index));
      series.stream() << csv_header(metrics_fields()) << '\n';
      for (const MetricsSample& sample : sampler.samples())
        series.stream() << csv_row(metrics_fields(), sample) << '\n';
      series.commit();
    }
  } catch (const Interrupted&) {
    throw;  // the run is abandoned, not failed: a resumed sweep runs it again
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  m.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.error) {
    for (const auto& f : run_fields())
      r.values[f.name] = f.get(m);
  } else {
    r.values["wall_time"] = m.wall_time;
  }
  return r;
}

std::string run_field_unit(const std::string& name) {
  for (const auto& f : run_fields()) {
    if (f.name == name) return f.unit;
  }
  return "";
}

// A sweep folder continued by a build other than the one that started it: its runs.csv will
// mix results of both.
void warn_builds(const std::string& what, const nlohmann::json& recorded) {
  const std::vector<std::string> diffs = build_differences(recorded);
  if (diffs.empty()) return;
  fmt::print(stderr, "covsim: warning: {} by a different build; its results will mix builds:\n",
             what);
  for (const std::string& d : diffs)
    fmt::print(stderr, "  {}\n", d);
}

std::string csv_value(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_null()) return "null";
  return v.dump();
}

}  // namespace

double SweepResult::number(const std::string& field) const {
  const auto it = values.find(field);
  if (it == values.end()) return NAN;
  if (it->is_boolean()) return it->get<bool>() ? 1.0 : 0.0;
  return it->is_number() ? it->get<double>() : NAN;
}

bool SweepResult::converged() const {
  const auto it = values.find("converged");
  return it != values.end() && it->is_boolean() && it->get<bool>();
}

std::string SweepResult::fingerprint() const {
  const auto it = values.find("fingerprint");
  return it != values.end() && it->is_string() ? it->get<std::string>() : "";
}

std::vector<std::string> sweep_metrics() {
  std::vector<std::string> m;
  for (const auto& f : run_fields()) {
    if (f.summarized) m.push_back(f.name);
  }
  return m;
}

std::vector<SweepResult> run_sweep(const SweepSpec& spec, const fs::path& dir,
                                   const SweepOptions& options) {
  fs::create_directories(dir / "runs");
  // The folder remembers its sweep, so a resume cannot mix two sweeps' results, and the
  // build that started it, so that a resume by another build says so.
  const nlohmann::json resolved = to_json(spec);
  if (std::ifstream in(dir / "sweep.json"); in) {
    nlohmann::json held;
    try {
      held = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error&) {
    }
    const nlohmann::json held_build = held.is_object() && held.contains("provenance")
                                          ? held.at("provenance")
                                          : nlohmann::json::object();
    if (held.is_object()) held.erase("provenance");
    if (held != resolved) {
      throw std::runtime_error(dir.string() +
                               " holds results of a different sweep; use another output folder");
    }
    warn_builds(dir.string() + " was started", held_build);
  } else {
    nlohmann::json with_build = resolved;
    with_build["provenance"] = this_build();
    AtomicFile f(dir / "sweep.json");
    f.stream() << with_build.dump() << '\n';
    f.commit();
  }
  std::vector<SweepRun> all = spec.runs();
  std::vector<SweepRun> mine;
  for (const SweepRun& r : all) {
    if (r.index % options.shards == options.shard) mine.push_back(r);
  }
  std::vector<SweepResult> results(mine.size());
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    if (auto done = from_json(dir / "runs" / fmt::format("{}.json", mine[k].index));
        done && done->index == mine[k].index) {
      results[k] = *done;
    } else {
      todo.push_back(k);
    }
  }
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::size_t finished = mine.size() - todo.size(), failed = 0;
  for (const SweepResult& r : results)
    failed += r.error ? 1 : 0;
  const auto start = std::chrono::steady_clock::now();
  const bool tty = isatty(STDERR_FILENO) != 0;
  auto report = [&] {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t ran = finished - (mine.size() - todo.size());
    const double left =
        ran > 0 ? elapsed / static_cast<double>(ran) * static_cast<double>(mine.size() - finished)
                : 0.0;
    const std::string line = fmt::format("sweep: {}/{} runs done, {} failed, about {:.0f} s left",
                                         finished, mine.size(), failed, left);
    if (tty)
      fmt::print(stderr, "\r{:<70}", line);
    else
      fmt::print(stderr, "{}\n", line);
  };
  // An interrupt stops every worker after its current event; the runs done are kept.
  std::exception_ptr interrupted;
  auto worker = [&] {
    for (std::size_t t = next++; t < todo.size(); t = next++) {
      const std::size_t k = todo[t];
      SweepResult r;
      try {
        r = execute(spec, mine[k], dir, options.keep_series);
      } catch (const Interrupted&) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!interrupted) interrupted = std::current_exception();
        next = todo.size();
        return;
      }
      try {
        AtomicFile f(dir / "runs" / fmt::format("{}.json", r.index));
        f.stream() << to_json(r).dump() << '\n';
        f.commit();
      } catch (const std::exception& e) {  // a full disk, say: this run's error
        r.error = fmt::format("cannot write its result: {}", e.what());
        r.values.clear();
      }
      std::lock_guard<std::mutex> lock(mutex);
      results[k] = std::move(r);
      ++finished;
      failed += results[k].error ? 1 : 0;
      if (options.progress) report();
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t j = 1; j < std::max<std::size_t>(1, options.jobs); ++j)
    threads.emplace_back(worker);
  worker();
  for (auto& t : threads)
    t.join();
  if (options.progress && tty) fmt::print(stderr, "\n");
  if (interrupted) std::rethrow_exception(interrupted);
  return results;
}

std::vector<SweepResult> merge_sweeps(const std::vector<fs::path>& dirs, const fs::path& out,
                                      SweepSpec& merged, const std::string& group,
                                      FigureFormat format) {
  if (dirs.empty()) throw std::runtime_error("nothing to merge");
  nlohmann::json resolved, first_build;
  for (const fs::path& d : dirs) {
    std::ifstream in(d / "sweep.json");
    if (!in) throw std::runtime_error(d.string() + ": not a sweep folder (no sweep.json)");
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
      throw std::runtime_error(d.string() + "/sweep.json: " + e.what());
    }
    const nlohmann::json build =
        j.is_object() && j.contains("provenance") ? j.at("provenance") : nlohmann::json::object();
    if (j.is_object()) j.erase("provenance");
    if (resolved.is_null()) {
      resolved = j;
      first_build = build;
    }
    if (j != resolved)
      throw std::runtime_error(d.string() + " holds a different sweep from " +
                               dirs.front().string());
    if (build != first_build) {
      fmt::print(stderr, "covsim: warning: {} and {} were run by different builds:\n",
                 dirs.front().string(), d.string());
      for (const auto& [key, value] : first_build.items()) {
        if (!build.contains(key) || build.at(key) != value)
          fmt::print(stderr, "  {}: {} and {}\n", key, value.dump(),
                     build.contains(key) ? build.at(key).dump() : "unknown");
      }
    }
  }
  merged = sweep_from_json(resolved);
  const std::size_t total = merged.runs().size();
  std::vector<std::optional<SweepResult>> found(total);
  for (const fs::path& d : dirs) {
    for (std::size_t i = 0; i < total; ++i) {
      if (found[i]) continue;
      if (auto r = from_json(d / "runs" / fmt::format("{}.json", i)); r && r->index == i)
        found[i] = *r;
    }
  }
  std::vector<SweepResult> results;
  std::size_t missing = 0;
  for (const auto& r : found) {
    if (r)
      results.push_back(*r);
    else
      ++missing;
  }
  if (missing > 0)
    throw std::runtime_error(
        fmt::format("{} of {} runs are in none of the folders", missing, total));
  fs::create_directories(out / "runs");
  for (const SweepResult& r : results) {
    AtomicFile f(out / "runs" / fmt::format("{}.json", r.index));
    f.stream() << to_json(r).dump() << '\n';
    f.commit();
  }
  // Series kept with --keep-series come along.
  for (const fs::path& d : dirs) {
    for (std::size_t i = 0; i < total; ++i) {
      const fs::path series = d / "runs" / fmt::format("{}.metrics.csv", i);
      std::error_code ec;
      if (fs::exists(series, ec) && !fs::equivalent(d, out, ec))
        fs::copy_file(series, out / "runs" / series.filename(),
                      fs::copy_options::overwrite_existing, ec);
    }
  }
  AtomicFile spec_file(out / "sweep.json");
  nlohmann::json with_build = resolved;
  with_build["provenance"] = first_build;
  spec_file.stream() << with_build.dump() << '\n';
  spec_file.commit();
  write_runs_csv(out / "runs.csv", merged, results);
  write_summary_csv(out / "summary.csv", merged, results);
  write_sweep_plots(out, merged, results, group, format);
  return results;
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
      // Modes need a sample to split: at least kModesMinSample runs (analysis/statistics).
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

std::vector<SweepChart> sweep_charts(const SweepSpec& spec, const std::vector<SweepResult>& results,
                                     const std::string& group) {
  std::optional<std::size_t> group_index;
  for (std::size_t q = 0; q < spec.parameters.size(); ++q) {
    if (spec.parameters[q] == group) group_index = q;
  }
  if (!group.empty() && !group_index) {
    throw std::invalid_argument("--group: \"" + group + "\" is not a swept parameter");
  }
  std::vector<SweepChart> charts;
  const std::vector<SweepRun> runs = spec.runs();
  // Parameters that take more than one value: only these name the lines.
  std::vector<bool> varies(spec.parameters.size(), false);
  for (std::size_t q = 0; q < spec.parameters.size(); ++q) {
    for (const auto& s : spec.settings)
      varies[q] = varies[q] || s[q] != spec.settings.front()[q];
  }
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) {
    // Only parameters that are numbers and take at least two values make an x axis; null
    // (an unlimited value, such as an infinite sensor range) is left off the axis.
    bool numeric = true;
    std::set<double> values;
    for (const auto& s : spec.settings) {
      numeric = numeric && (s[p].is_number() || s[p].is_null());
      if (numeric && s[p].is_number()) values.insert(s[p].get<double>());
    }
    if (!numeric || values.size() < 2 || (group_index && *group_index == p)) continue;
    for (const std::string& metric : sweep_metrics()) {
      if (metric == "wall_time") continue;
      // One line per value of the grouping parameter (pooling the others), or else per
      // combination of the other varying parameters; points at this parameter's values.
      std::map<std::string, std::map<double, std::vector<double>>> lines;
      for (const SweepResult& r : results) {
        const SweepRun& run = runs.at(r.index);
        if (r.error || run.values[p].is_null()) continue;
        const double y = r.number(metric);
        if (std::isnan(y)) continue;  // not taken by that run
        std::string label;
        for (std::size_t q = 0; q < spec.parameters.size(); ++q) {
          const bool names_line = group_index ? q == *group_index : varies[q];
          if (q != p && names_line)
            label +=
                (label.empty() ? "" : ", ") + spec.parameters[q] + " = " + csv_value(run.values[q]);
        }
        lines[label.empty() ? "mean over seeds" : label][run.values[p].get<double>()].push_back(y);
      }
      std::vector<ChartSeries> series;
      for (const auto& [label, points] : lines) {
        ChartSeries s{label, {}, true, false, {}};
        for (const auto& [x, ys] : points) {
          const SampleSummary sum = summarize_sample(ys);
          s.points.push_back({x, sum.mean, sum.mean - sum.ci95, sum.mean + sum.ci95});
          for (double y : ys)
            s.samples.emplace_back(x, y);
        }
        series.push_back(std::move(s));
      }
      const auto with_unit = [](const std::string& name, const std::string& unit) {
        return unit.empty() ? name : fmt::format("{} [{}]", name, unit);
      };
      LineChart chart;
      chart.title = fmt::format("{} (mean, 95% confidence band; dots: runs)", metric);
      chart.x_label = with_unit(spec.parameters[p], scenario_key_unit(spec.parameters[p]));
      chart.y_label = with_unit(metric, run_field_unit(metric));
      chart.series = std::move(series);
      charts.push_back({fmt::format("{}_vs_{}", metric, spec.parameters[p]), std::move(chart)});
    }
  }
  return charts;
}

std::vector<fs::path> write_sweep_plots(const fs::path& dir, const SweepSpec& spec,
                                        const std::vector<SweepResult>& results,
                                        const std::string& group, FigureFormat format) {
  std::vector<fs::path> written;
  for (const SweepChart& c : sweep_charts(spec, results, group)) {
    const fs::path file = dir / fmt::format("{}.{}", c.name, extension(format));
    AtomicFile f(file);
    f.stream() << draw_line_chart(c.chart, FigureFile{format, 0});
    f.commit();
    written.push_back(file);
  }
  return written;
}

}  // namespace covsim
