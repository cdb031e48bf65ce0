#pragma once
// Records a run as it goes: DIR/trajectory.csv (a row per robot per motion step, the start
// included, so joining a robot's rows draws its path; trajectory.csv.gz, gzip, when
// compressed) and DIR/metrics.csv (a row per sample), both written to ".partial" files that
// appear only on commit(). It keeps what it wrote (each robot's track and the cost series)
// for the figures. A trajectory period thins the recording: a robot's row is written when
// that much time has passed since its last, and its last state at the end of the run.
#include <array>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/records/csv_metadata.hpp"
#include "analysis/records/known_cells.hpp"
#include "analysis/records/planner_map_log.hpp"
#include "analysis/records/robot_track.hpp"
#include "io/atomic_file.hpp"
#include "robot/coverage_controller.hpp"
#include "scenarios/recording_config.hpp"
#include "sim/metrics_sampler.hpp"

struct z_stream_s;  // zlib's, kept out of this header

namespace covsim {

// One row of trajectory.csv.
struct TrajectoryRow {
  double t;
  std::uint32_t robot;
  Vec2 position, virtual_generator, virtual_target, real_target;
};

// trajectory.csv's columns, in the order of a row's values above: the writer's header and
// what the reader expects.
inline constexpr std::array<std::string_view, 10> kTrajectoryColumns{
    "t", "robot", "x", "y", "vx", "vy", "tx", "ty", "rx", "ry"};
// The columns joined by commas.
std::string trajectory_header();
// The columns with their units and meanings, in kTrajectoryColumns' order (for the CSVW
// metadata written beside the file).
std::vector<CsvColumn> trajectory_columns();

// "trajectory.csv", or "trajectory.csv.gz" when compressed.
std::string_view trajectory_file_name(bool compressed);

// Formats trajectory.csv's rows: the bytes fmt's "{}" gives (shortest round-trip doubles),
// without parsing a format string per row, and formatting a value once where the row repeats
// it (the time across a step's rows; a target equal to the generator).
class TrajectoryRowFormat {
 public:
  void append(std::string& out, const TrajectoryRow& row);

 private:
  double t_ = 0.0;
  bool t_set_ = false;
  char t_text_[32] = {};
  std::size_t t_size_ = 0;
};

// Bytes deflated into one gzip stream (RFC 1952) as they come, and written to `out`: what
// gzip, Python's gzip module, pandas and numpy read.
class GzipWriter {
 public:
  explicit GzipWriter(std::ostream& out);
  GzipWriter(const GzipWriter&) = delete;
  GzipWriter& operator=(const GzipWriter&) = delete;
  ~GzipWriter();
  void write(std::string_view bytes);
  // Ends the stream: what is left, then the trailer (CRC-32 and length).
  void finish();

 private:
  void deflate_into_out(int flush);
  std::ostream& out_;
  std::unique_ptr<z_stream_s> z_;
  std::vector<char> chunk_;
  bool finished_ = false;
};

class RunRecorder final : public CoverageObserver {
 public:
  // recording: the scenario's (the trajectory period: seconds between a robot's rows, 0 for
  // every motion step; whether to compress). track_tolerance: the tracks'
  // (RobotTrack::tolerance; track_tolerance(Ω's diameter) for the figures), the files are
  // exact.
  RunRecorder(const std::filesystem::path& dir, const std::vector<Vec2>& starts,
              const RecordingConfig& recording = {}, double track_tolerance = 0.0);
  void on_motion(SimTime t, const Robot& r) override;
  void on_sample(SimTime t, const CoverageController& c) override;
  // A last sample at the end of the run; for robots that mapped Ω, DIR/map.csv: per cell of
  // Ω's known-area lattice its centre and when the maps first held it (x, y, t; inf: never),
  // and with mapping.robot_maps when each robot's own did (r0, r1, ...); for planners that
  // keep a map of their own (planner.map "sensed"), DIR/planner_map.csv: the walls their
  // maps gained and the ways they had ahead, at each sample (PlannerMapRecord).
  void on_finish(SimTime t, const CoverageController& c) override;
  // Moves the files into place.
  void commit();
  // The map's cells (empty when Ω was known).
  const KnownCells& known_cells() const { return known_; }
  // What the planners with maps of their own planned on (empty for the others).
  const PlannerMapRecord& planner_maps() const { return planner_log_.record(); }

  const std::vector<RobotTrack>& tracks() const { return tracks_; }
  const std::vector<MetricsSample>& samples() const { return sampler_.samples(); }

 private:
  void flush(bool force);
  void write(double t, std::uint32_t robot, Vec2 p, Vec2 v, Vec2 vt, Vec2 rt);
  AtomicFile trajectory_, metrics_;
  std::unique_ptr<GzipWriter> gzip_;  // set when trajectory_ is compressed
  std::string trajectory_buffer_, metrics_buffer_;
  TrajectoryRowFormat row_format_;
  double period_;
  std::vector<RobotTrack> tracks_;
  // A robot's latest state not yet written (thinned recordings).
  struct Pending {
    bool set = false;
    Vec2 p, v, vt, rt;
  };
  std::vector<Pending> pending_;
  MetricsSampler sampler_;
  std::filesystem::path dir_;
  std::unique_ptr<AtomicFile> map_, planner_map_;
  KnownCells known_;
  PlannerMapLog planner_log_;
};

}  // namespace covsim
