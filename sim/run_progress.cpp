#include "sim/run_progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace covsim {

namespace {
constexpr std::chrono::milliseconds kQuiet{1000};  // runs shorter than this show nothing
constexpr std::chrono::milliseconds kEvery{500};   // between two lines
constexpr int kWidth = 78;
}  // namespace

bool RunProgress::stderr_is_terminal() {
  return isatty(STDERR_FILENO) != 0;
}

RunProgress::RunProgress(CoverageObserver* inner, bool shown)
    : inner_(inner), shown_(shown), start_(std::chrono::steady_clock::now()), last_(start_) {}

RunProgress::~RunProgress() {
  clear();  // also when the run ends by an exception (an interrupt)
}

void RunProgress::clear() {
  if (!drawn_) return;
  fmt::print(stderr, "\r{:<{}}\r", "", kWidth);
  std::fflush(stderr);
  drawn_ = false;
}

void RunProgress::on_motion(SimTime t, const Robot& r) {
  if (inner_ != nullptr) inner_->on_motion(t, r);
}

void RunProgress::on_sample(SimTime t, const CoverageController& c) {
  if (inner_ != nullptr) inner_->on_sample(t, c);
  if (!shown_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < kQuiet || now - last_ < kEvery) return;
  last_ = now;
  std::size_t settled = 0;
  for (const Robot& r : c.robots())
    settled += r.stable ? 1 : 0;
  const double max_time = c.config().max_time.seconds();
  const std::string line =
      fmt::format("run: t = {:.1f} of {:.0f} s simulated ({:.0f}%), {}/{} robots settled, {:.0f} s",
                  t.seconds(), max_time, 100.0 * t.seconds() / max_time, settled, c.robots().size(),
                  std::chrono::duration<double>(now - start_).count());
  fmt::print(stderr, "\r{:<{}}", line, kWidth);
  std::fflush(stderr);
  drawn_ = true;
}

void RunProgress::on_finish(SimTime t, const CoverageController& c) {
  if (inner_ != nullptr) inner_->on_finish(t, c);
  clear();
}

}  // namespace covsim
