#include "sim/run_progress.hpp"

#include <fmt/format.h>

namespace covsim {

RunProgress::RunProgress(CoverageObserver* inner, bool shown) : inner_(inner), line_(shown) {}

void RunProgress::on_motion(SimTime t, const Robot& r) {
  if (inner_ != nullptr) inner_->on_motion(t, r);
}

void RunProgress::on_sample(SimTime t, const CoverageController& c) {
  if (inner_ != nullptr) inner_->on_sample(t, c);
  if (!line_.due()) return;
  std::size_t settled = 0;
  for (const Robot& r : c.robots())
    settled += r.stable ? 1 : 0;
  const double max_time = c.config().max_time.seconds();
  // A run ends at convergence, seldom at max_time: the pace gives a bound, not a forecast.
  const double pace = t.seconds() > 0.0 ? line_.seconds() / t.seconds() : 0.0;
  line_.show(fmt::format(
      "run: t = {:.1f} of {:.0f} s simulated ({:.0f}%), {}/{} robots settled, {:.0f} s, at most "
      "{:.0f} s more at this pace",
      t.seconds(), max_time, 100.0 * t.seconds() / max_time, settled, c.robots().size(),
      line_.seconds(), pace * (max_time - t.seconds())));
}

void RunProgress::on_finish(SimTime t, const CoverageController& c) {
  if (inner_ != nullptr) inner_->on_finish(t, c);
  line_.clear();
}

}  // namespace covsim
