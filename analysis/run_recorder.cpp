#include "analysis/run_recorder.hpp"

#include <fmt/format.h>

#include "analysis/result_fields.hpp"

namespace covsim {

RunRecorder::RunRecorder(const std::filesystem::path& dir, const std::vector<Vec2>& starts,
                         double trajectory_period, double track_tolerance)
    : trajectory_(dir / "trajectory.csv"),
      metrics_(dir / "metrics.csv"),
      period_(trajectory_period),
      tracks_(starts.size()),
      pending_(starts.size()) {
  for (RobotTrack& k : tracks_)
    k.tolerance = track_tolerance;
  trajectory_buffer_ = "t,robot,x,y,vx,vy,tx,ty,rx,ry\n";
  metrics_buffer_ = csv_header(metrics_fields()) + "\n";
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const Vec2 s = starts[i];
    write(0.0, static_cast<std::uint32_t>(i), s, s, s, s);
  }
}

void RunRecorder::write(double t, std::uint32_t robot, Vec2 p, Vec2 v, Vec2 vt, Vec2 rt) {
  fmt::format_to(std::back_inserter(trajectory_buffer_), "{},{},{},{},{},{},{},{},{},{}\n", t,
                 robot, p.x, p.y, v.x, v.y, vt.x, vt.y, rt.x, rt.y);
  tracks_[robot].push(t, p, v, vt, rt);
}

void RunRecorder::on_motion(SimTime t, const Robot& r) {
  const double now = t.seconds();
  RobotTrack& k = tracks_[r.id];
  if (period_ > 0.0 && now - k.t.back() < period_) {
    pending_[r.id] = {true, r.position, r.virtual_generator, r.virtual_target, r.real_target};
    return;
  }
  pending_[r.id].set = false;
  write(now, r.id, r.position, r.virtual_generator, r.virtual_target, r.real_target);
  flush(false);
}

void RunRecorder::on_sample(SimTime t, const CoverageController& controller) {
  sampler_.on_sample(t, controller);
  metrics_buffer_ += csv_row(metrics_fields(), sampler_.samples().back()) + "\n";
  flush(false);
}

void RunRecorder::on_finish(SimTime t, const CoverageController& c) {
  // A thinned robot's last state, stamped with the end time (it stood there since its last
  // step), so that rows stay in time order.
  for (std::uint32_t i = 0; i < pending_.size(); ++i) {
    const Pending& q = pending_[i];
    if (q.set) write(t.seconds(), i, q.p, q.v, q.vt, q.rt);
    pending_[i].set = false;
  }
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
