#include "analysis/run_recorder.hpp"

#include <fmt/format.h>

#include "analysis/result_fields.hpp"

namespace covsim {

RunRecorder::RunRecorder(const std::filesystem::path& dir, const std::vector<Vec2>& starts)
    : trajectory_(dir / "trajectory.csv"), metrics_(dir / "metrics.csv") {
  trajectory_buffer_ = "t,robot,x,y,vx,vy,tx,ty,rx,ry\n";
  metrics_buffer_ = csv_header(metrics_fields()) + "\n";
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const Vec2 s = starts[i];
    fmt::format_to(std::back_inserter(trajectory_buffer_), "0,{},{},{},{},{},{},{},{},{}\n", i, s.x,
                   s.y, s.x, s.y, s.x, s.y, s.x, s.y);
    real_.push_back({starts[i]});
    virtual_.push_back({starts[i]});
  }
}

void RunRecorder::on_motion(SimTime t, const Robot& r) {
  fmt::format_to(std::back_inserter(trajectory_buffer_), "{},{},{},{},{},{},{},{},{},{}\n",
                 t.seconds(), r.id, r.position.x, r.position.y, r.virtual_generator.x,
                 r.virtual_generator.y, r.virtual_target.x, r.virtual_target.y, r.real_target.x,
                 r.real_target.y);
  if (!(real_[r.id].back() == r.position)) real_[r.id].push_back(r.position);
  if (!(virtual_[r.id].back() == r.virtual_generator))
    virtual_[r.id].push_back(r.virtual_generator);
  flush(false);
}

void RunRecorder::on_sample(SimTime t, const CoverageController& controller) {
  sampler_.on_sample(t, controller);
  metrics_buffer_ += csv_row(metrics_fields(), sampler_.samples().back()) + "\n";
  flush(false);
}

void RunRecorder::on_finish(SimTime t, const CoverageController& c) {
  const std::size_t before = sampler_.samples().size();
  sampler_.on_finish(t, c);
  if (sampler_.samples().size() > before) {
    metrics_buffer_ += csv_row(metrics_fields(), sampler_.samples().back()) + "\n";
    flush(false);
  }
}

void RunRecorder::flush(bool force) {
  if (force || trajectory_buffer_.size() > (1 << 16)) {
    trajectory_.stream() << trajectory_buffer_;
    trajectory_buffer_.clear();
  }
  if (force || metrics_buffer_.size() > (1 << 16)) {
    metrics_.stream() << metrics_buffer_;
    metrics_buffer_.clear();
  }
}

void RunRecorder::commit() {
  flush(true);
  trajectory_.commit();
  metrics_.commit();
}

}  // namespace covsim
