#pragma once
// The event trace: a line-oriented text file, so that two traces can also be compared with
// ordinary tools. Format version 1:
//
//   covsim-trace 1
//   seed <decimal>
//   scenario_hash <16 hex digits>
//   <key> <value>              (further header entries, one line each, optional)
//   events
//   <index> <time_ns> <kind> <entity> <fingerprint, 16 hex digits>
//   ...
//
// Each record carries the running fingerprint after that event, so the first record where
// two traces differ is the first event where the runs diverged.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/sim_time.hpp"
#include "io/atomic_file.hpp"

namespace covsim {

// A trace that is not one (malformed, truncated, or edited): bad input, not a divergence.
struct TraceFormatError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct TraceHeader {
  int version = 1;
  std::uint64_t seed = 0;
  std::uint64_t scenario_hash = 0;
  std::vector<std::pair<std::string, std::string>> entries;  // values hold no newline
};

struct TraceRecord {
  std::uint64_t index = 0;
  SimTime time;
  std::string kind;
  std::uint32_t entity = 0;
  std::uint64_t fingerprint = 0;
  friend bool operator==(const TraceRecord&, const TraceRecord&) = default;
};

// Where the kernel sends each dispatched event, with the running fingerprint after it.
class TraceSink {
 public:
  virtual ~TraceSink() = default;
  virtual void record(std::uint64_t index, SimTime t, const std::string& kind, std::uint32_t entity,
                      std::uint64_t fingerprint) = 0;
};

class TraceWriter final : public TraceSink {
 public:
  TraceWriter(std::filesystem::path path, const TraceHeader& header);
  void record(std::uint64_t index, SimTime t, const std::string& kind, std::uint32_t entity,
              std::uint64_t fingerprint) override;
  // Writes the end record (the number of events and the last fingerprint, so that a cut
  // trace is told from a diverging run); the file appears only now (see AtomicFile).
  void commit();

 private:
  void flush_buffer();
  AtomicFile file_;
  std::string buffer_;
  std::uint64_t records_ = 0, last_fingerprint_ = 0;
};

class TraceReader {
 public:
  // Throws TraceFormatError naming the file and line for anything malformed.
  explicit TraceReader(std::filesystem::path path);
  const TraceHeader& header() const { return header_; }
  // The next event record; nullopt after the last one. A trace without its end record, or
  // whose end record disagrees with its events, throws TraceFormatError.
  std::optional<TraceRecord> next();

 private:
  [[noreturn]] void fail(const std::string& what) const;
  // A record is about a hundred bytes: a longer line (/dev/zero) ends the read.
  static constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;
  bool read_line(std::string& line);
  std::filesystem::path path_;
  std::ifstream in_;
  std::uint64_t line_ = 0, records_ = 0, last_fingerprint_ = 0;
  bool ended_ = false;
  TraceHeader header_;
};

struct TraceDivergence {
  std::uint64_t index;              // position of the first differing record
  std::optional<TraceRecord> a, b;  // nullopt where that trace had already ended
};

// The first record where the two traces differ, or nullopt if they are equal.
std::optional<TraceDivergence> first_divergence(TraceReader& a, TraceReader& b);

}  // namespace covsim
