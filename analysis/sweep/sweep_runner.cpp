#include "analysis/sweep/sweep_runner.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>

#include "analysis/records/result_fields.hpp"
#include "analysis/sweep/sweep_folder.hpp"
#include "io/atomic_file.hpp"
#include "io/interrupt.hpp"
#include "scenarios/scenario_error.hpp"
#include "sim/coverage_run.hpp"
#include "sim/metrics_sampler.hpp"
#include "sim/provenance.hpp"

namespace covsim {

namespace fs = std::filesystem;

namespace {

// A run's series that could not be written (a full disk): the machine's failure, not the
// run's, so the run is not recorded as done and a resumed sweep runs it again.
struct SeriesWriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

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
      try {
        AtomicFile series(dir / "runs" / fmt::format("{}.metrics.csv", run.index));
        series.stream() << csv_header(metrics_fields()) << '\n';
        for (const MetricsSample& sample : sampler.samples())
          series.stream() << csv_row(metrics_fields(), sample) << '\n';
        series.commit();
      } catch (const std::exception& e) {
        throw SeriesWriteError(e.what());
      }
    }
  } catch (const Interrupted&) {
    throw;  // the run is abandoned, not failed: a resumed sweep runs it again
  } catch (const SeriesWriteError&) {
    throw;
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

// A wall-clock duration as a person reads it: "0.4 s", "12 s", "3 min 20 s", "2 h 05 min".
std::string duration_text(double seconds) {
  if (seconds < 9.95) return fmt::format("{:.1f} s", seconds);
  const auto s = static_cast<long long>(std::llround(seconds));
  if (s < 60) return fmt::format("{} s", s);
  if (s < 3600) return fmt::format("{} min {:02} s", s / 60, s % 60);
  return fmt::format("{} h {:02} min", s / 3600, (s % 3600) / 60);
}

// Progress on stderr: one line rewritten in place on a terminal, else one line per run.
class ProgressLine {
 public:
  ProgressLine(bool on, std::size_t total, std::size_t done_before)
      : on_(on), tty_(isatty(STDERR_FILENO) != 0), total_(total), before_(done_before) {}
  void report(std::size_t finished, std::size_t failed) const {
    if (!on_) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const std::size_t ran = finished - before_;
    // The time left from the runs of this process alone (runs found done took no time); none
    // before one has run.
    std::string when;
    if (finished == total_)
      when = fmt::format(", {} here", duration_text(elapsed));
    else if (ran > 0)
      when = fmt::format(", about {} left", duration_text(elapsed / static_cast<double>(ran) *
                                                          static_cast<double>(total_ - finished)));
    const std::string line =
        fmt::format("sweep: {}/{} runs done, {} failed{}", finished, total_, failed, when);
    if (tty_)
      fmt::print(stderr, "\r{:<70}", line);
    else
      fmt::print(stderr, "{}\n", line);
  }
  void finish() const {
    if (on_ && tty_) fmt::print(stderr, "\n");
  }

 private:
  bool on_, tty_;
  std::size_t total_, before_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

std::vector<SweepResult> run_sweep(const SweepSpec& spec, const fs::path& dir,
                                   const SweepOptions& options) {
  fs::create_directories(dir / "runs");
  claim_sweep_folder(spec, dir);
  // This shard's runs; those whose results the folder holds are done.
  std::vector<SweepRun> mine;
  for (const SweepRun& r : spec.runs()) {
    if (r.index % options.shards == options.shard) mine.push_back(r);
  }
  std::vector<SweepResult> results(mine.size());
  std::vector<std::size_t> todo;
  std::size_t failed = 0;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    if (auto done = read_result(dir, mine[k].index)) {
      results[k] = *done;
      failed += done->error ? 1 : 0;
    } else {
      todo.push_back(k);
    }
  }
  std::size_t finished = mine.size() - todo.size();
  const ProgressLine progress(options.progress, mine.size(), finished);
  if (options.on_progress) options.on_progress(finished, failed, mine.size());
  // The workers take the runs to do in order; an interrupt stops every worker after its
  // current event, and the runs done are kept.
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::exception_ptr interrupted;
  auto worker = [&] {
    for (std::size_t t = next++; t < todo.size(); t = next++) {
      const std::size_t k = todo[t];
      SweepResult r;
      bool recorded = true;
      try {
        r = execute(spec, mine[k], dir, options.keep_series);
      } catch (const Interrupted&) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!interrupted) interrupted = std::current_exception();
        next = todo.size();
        return;
      } catch (const SeriesWriteError& e) {  // not recorded: a resumed sweep runs it again
        r.index = mine[k].index;
        r.error = fmt::format("cannot write its metrics series: {}", e.what());
        recorded = false;
      }
      try {
        if (recorded) write_result(dir, r);
      } catch (const std::exception& e) {  // a full disk, say: this run's error
        r.error = fmt::format("cannot write its result: {}", e.what());
        r.values.clear();
      }
      std::lock_guard<std::mutex> lock(mutex);
      results[k] = std::move(r);
      ++finished;
      failed += results[k].error ? 1 : 0;
      try {
        progress.report(finished, failed);
      } catch (...) {
        // stderr closed or full: the progress line is lost, not the sweep
      }
      if (options.on_progress) options.on_progress(finished, failed, mine.size());
    }
  };
  // Anything else a worker meets (memory, say) stops the others and is the sweep's error,
  // raised once every thread has ended.
  std::exception_ptr failure;
  auto guarded_worker = [&] {
    try {
      worker();
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      next = todo.size();
    }
  };
  std::vector<std::thread> threads;
  // No more threads than runs to do: a large --jobs on a small sweep costs nothing.
  const std::size_t workers = std::min(std::max<std::size_t>(1, options.jobs), todo.size());
  threads.reserve(workers);  // no allocation, hence no throw, with threads running
  for (std::size_t j = 1; j < workers; ++j) {
    try {
      threads.emplace_back(guarded_worker);
    } catch (const std::system_error&) {
      break;  // the system gives no more threads: the runs go on in those there are
    }
  }
  guarded_worker();
  for (auto& t : threads)
    t.join();
  try {
    progress.finish();
  } catch (...) {
  }
  if (interrupted) std::rethrow_exception(interrupted);
  if (failure) std::rethrow_exception(failure);
  return results;
}

std::vector<SweepResult> merge_sweeps(const std::vector<fs::path>& dirs, const fs::path& out,
                                      SweepSpec& merged) {
  if (dirs.empty()) throw std::runtime_error("nothing to merge");
  // One sweep in every folder; builds that differ are named.
  const SweepFolderRecord first = read_sweep_folder(dirs.front());
  for (auto d = dirs.begin() + 1; d != dirs.end(); ++d) {
    const SweepFolderRecord held = read_sweep_folder(*d);
    if (held.sweep != first.sweep)
      throw std::runtime_error(d->string() + " holds a different sweep from " +
                               dirs.front().string());
    const std::vector<std::string> diffs = build_differences(first.provenance, held.provenance);
    if (diffs.empty()) continue;
    fmt::print(stderr, "covsim: warning: {} and {} were run by different builds:\n",
               dirs.front().string(), d->string());
    for (const std::string& line : diffs)
      fmt::print(stderr, "  {}\n", line);
  }
  merged = sweep_of_folder(dirs.front());
  // Every run's result from the first folder that holds it.
  const std::size_t total = merged.runs().size();
  std::vector<SweepResult> results;
  std::size_t missing = 0;
  for (std::size_t i = 0; i < total; ++i) {
    std::optional<SweepResult> r;
    for (std::size_t k = 0; k < dirs.size() && !r; ++k)
      r = read_result(dirs[k], i);
    if (r)
      results.push_back(*r);
    else
      ++missing;
  }
  if (missing > 0)
    throw std::runtime_error(
        fmt::format("{} of {} runs are in none of the folders", missing, total));
  fs::create_directories(out / "runs");
  for (const SweepResult& r : results)
    write_result(out, r);
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
  write_sweep_folder(out, first);
  write_runs_csv(out / "runs.csv", merged, results);
  write_summary_csv(out / "summary.csv", merged, results);
  return results;
}

}  // namespace covsim
