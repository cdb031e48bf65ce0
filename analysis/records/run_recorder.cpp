#include "analysis/records/run_recorder.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "robot/mapping.hpp"

#include "analysis/records/result_fields.hpp"

namespace covsim {

namespace {

// Bitwise: -0.0 and 0.0 are written differently ("-0", "0").
bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(Vec2 a, Vec2 b) {
  return same(a.x, b.x) && same(a.y, b.y);
}

// fmt's "{}" compiled once: the same digits and layout as the run-time format string.
char* put(char* p, double x) {
  return fmt::format_to(p, FMT_COMPILE("{}"), x);
}

}  // namespace

std::string trajectory_header() {
  std::string out;
  for (std::string_view c : kTrajectoryColumns)
    (out += out.empty() ? "" : ",") += c;
  return out;
}

std::vector<CsvColumn> trajectory_columns() {
  using K = FieldKind;
  return {{"t", K::number, "s", "simulated time"},
          {"robot", K::integer, "", "the robot's index, in scenario order"},
          {"x", K::number, "m", "the robot's position"},
          {"y", K::number, "m", "the robot's position"},
          {"vx", K::number, "m", "its virtual generator"},
          {"vy", K::number, "m", "its virtual generator"},
          {"tx", K::number, "m", "its virtual target (the baselines: their loop-1 target)"},
          {"ty", K::number, "m", "its virtual target (the baselines: their loop-1 target)"},
          {"rx", K::number, "m", "its real target"},
          {"ry", K::number, "m", "its real target"}};
}

std::string_view trajectory_file_name(bool compressed) {
  return compressed ? "trajectory.csv.gz" : "trajectory.csv";
}

void TrajectoryRowFormat::append(std::string& out, const TrajectoryRow& row) {
  // fmt's shortest double is at most 24 characters ("-2.2250738585072014e-308"), a robot
  // index at most 10: a row is at most 9 × 24 + 10 + 10 separators.
  char line[256];
  if (!t_set_ || !same(row.t, t_)) {
    t_ = row.t;
    t_set_ = true;
    t_size_ = static_cast<std::size_t>(put(t_text_, row.t) - t_text_);
  }
  char* p = std::copy_n(t_text_, t_size_, line);
  *p++ = ',';
  p = fmt::format_to(p, FMT_COMPILE("{}"), row.robot);
  const Vec2 points[] = {row.position, row.virtual_generator, row.virtual_target, row.real_target};
  const char* previous = nullptr;  // the previous point's text
  for (std::size_t k = 0; k < 4; ++k) {
    *p++ = ',';
    char* begin = p;
    if (k > 0 && same(points[k], points[k - 1])) {
      p = std::copy(previous, static_cast<const char*>(begin) - 1, p);
    } else {
      p = put(p, points[k].x);
      *p++ = ',';
      p = put(p, points[k].y);
    }
    previous = begin;
  }
  *p++ = '\n';
  out.append(line, p);
}

GzipWriter::GzipWriter(std::ostream& out)
    : out_(out), z_(std::make_unique<z_stream_s>()), chunk_(1 << 16) {
  // windowBits 15 + 16: a gzip header and trailer around the deflate stream. Level 1: office's
  // trajectory 5.9 times smaller in 0.45 s; the default level (6) gains a fifth more for
  // four times the time, as much as formatting the rows costs.
  if (deflateInit2(z_.get(), Z_BEST_SPEED, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib: cannot start a gzip stream");
}

GzipWriter::~GzipWriter() {
  deflateEnd(z_.get());
}

void GzipWriter::write(std::string_view bytes) {
  if (finished_) throw std::logic_error("GzipWriter::write after finish");
  // zlib counts input in uInt: feed a very large string in pieces.
  while (!bytes.empty()) {
    const std::size_t n = std::min<std::size_t>(bytes.size(), 1u << 30);
    z_->next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    z_->avail_in = static_cast<uInt>(n);
    deflate_into_out(Z_NO_FLUSH);
    bytes.remove_prefix(n);
  }
}

void GzipWriter::finish() {
  if (finished_) return;
  z_->next_in = nullptr;
  z_->avail_in = 0;
  deflate_into_out(Z_FINISH);
  finished_ = true;
}

void GzipWriter::deflate_into_out(int flush) {
  // Until zlib has taken all the input (and, finishing, written the trailer): it stops
  // early only when the chunk is full.
  int rc = Z_OK;
  do {
    z_->next_out = reinterpret_cast<Bytef*>(chunk_.data());
    z_->avail_out = static_cast<uInt>(chunk_.size());
    rc = deflate(z_.get(), flush);
    if (rc == Z_STREAM_ERROR) throw std::runtime_error("zlib: deflate failed");
    out_.write(chunk_.data(), static_cast<std::streamsize>(chunk_.size() - z_->avail_out));
  } while (z_->avail_out == 0 || (flush == Z_FINISH && rc != Z_STREAM_END));
}

RunRecorder::RunRecorder(const std::filesystem::path& dir, const std::vector<Vec2>& starts,
                         const RecordingConfig& recording, double track_tolerance)
    : trajectory_(dir / trajectory_file_name(recording.compress)),
      metrics_(dir / "metrics.csv"),
      period_(recording.trajectory_period),
      tracks_(starts.size()),
      pending_(starts.size()),
      dir_(dir) {
  if (recording.compress) gzip_ = std::make_unique<GzipWriter>(trajectory_.stream());
  for (RobotTrack& k : tracks_)
    k.tolerance = track_tolerance;
  trajectory_buffer_ = trajectory_header() + "\n";
  metrics_buffer_ = csv_header(metrics_fields()) + "\n";
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const Vec2 s = starts[i];
    write(0.0, static_cast<std::uint32_t>(i), s, s, s, s);
  }
}

void RunRecorder::write(double t, std::uint32_t robot, Vec2 p, Vec2 v, Vec2 vt, Vec2 rt) {
  row_format_.append(trajectory_buffer_, TrajectoryRow{t, robot, p, v, vt, rt});
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
  planner_log_.record(t.seconds(), controller.robots());
}

void RunRecorder::on_finish(SimTime t, const CoverageController& c) {
  // A thinned robot's last state, stamped with the end time (it stood there since its last
  // step), so that rows stay in time order.
  for (std::uint32_t i = 0; i < pending_.size(); ++i) {
    const Pending& q = pending_[i];
    if (q.set) write(t.seconds(), i, q.p, q.v, q.vt, q.rt);
    pending_[i].set = false;
  }
  if (const Mapping* m = c.mapping()) {
    const KnownLattice& free = m->free_cells();
    known_.size = free.cell();
    map_ = std::make_unique<AtomicFile>(dir_ / "map.csv");
    const auto robots = static_cast<std::uint32_t>(m->has_robot_times() ? c.robots().size() : 0);
    known_.robots.assign(robots, {});
    std::string text = "x,y,t";
    for (std::uint32_t r = 0; r < robots; ++r)
      text += fmt::format(",r{}", r);
    text += "\n";
    const auto never = [](double since) { return std::isnan(since) ? INFINITY : since; };
    for (std::int32_t j = 0; j < free.ny(); ++j) {
      for (std::int32_t i = 0; i < free.nx(); ++i) {
        if (!free.at(i, j)) continue;
        const Vec2 p = free.centre(i, j);
        const double since = never(m->known_since(i, j));
        known_.cells.push_back({p, since});
        text += fmt::format("{},{},{}", p.x, p.y, since);
        for (std::uint32_t r = 0; r < robots; ++r) {
          const double own = never(m->known_since(r, i, j));
          known_.robots[r].push_back(own);
          text += fmt::format(",{}", own);
        }
        text += "\n";
      }
    }
    map_->stream() << text;
  }
  // What the planners planned on, where they keep a map of their own (planner.map "sensed").
  planner_log_.record(t.seconds(), c.robots());
  if (!planner_log_.record().empty()) {
    planner_map_ = std::make_unique<AtomicFile>(dir_ / "planner_map.csv");
    planner_map_->stream() << planner_log_.record().csv();
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
    // Compressed as the buffer fills: the whole file is never held in memory.
    if (gzip_)
      gzip_->write(trajectory_buffer_);
    else
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
  if (gzip_) gzip_->finish();
  trajectory_.commit();
  if (map_) map_->commit();
  if (planner_map_) planner_map_->commit();
  metrics_.commit();
  // The columns' units beside the two tables (CSVW metadata).
  std::vector<CsvColumn> metrics;
  for (const auto& f : metrics_fields())
    metrics.push_back({f.name, f.kind, f.unit, f.description});
  write_csv_metadata(dir_ / "metrics.csv", "covsim run: metrics samples", metrics);
  write_csv_metadata(dir_ / trajectory_file_name(gzip_ != nullptr),
                     "covsim run: a row per robot per motion step", trajectory_columns());
}

}  // namespace covsim
