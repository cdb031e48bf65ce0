#include "core/trace.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include <fmt/format.h>

#include "core/fingerprint.hpp"
#include "io/bounded_read.hpp"

namespace covsim {

namespace {
constexpr std::string_view kMagic = "covsim-trace";
constexpr std::size_t kFlushBytes = 1 << 16;

bool valid_key(const std::string& key) {
  return !key.empty() && key.find_first_of(" \t\n") == std::string::npos && key != "events";
}
}  // namespace

TraceWriter::TraceWriter(std::filesystem::path path, const TraceHeader& header)
    : file_(std::move(path)) {
  fmt::format_to(std::back_inserter(buffer_), "{} {}\nseed {}\nscenario_hash {}\n", kMagic,
                 header.version, header.seed, Fingerprint::to_hex(header.scenario_hash));
  for (const auto& [key, value] : header.entries) {
    if (!valid_key(key) || value.find('\n') != std::string::npos) {
      throw std::invalid_argument("trace header entry '" + key +
                                  "' is not a key without spaces and a one-line value");
    }
    fmt::format_to(std::back_inserter(buffer_), "{} {}\n", key, value);
  }
  buffer_ += "events\n";
}

void TraceWriter::record(std::uint64_t index, SimTime t, const std::string& kind,
                         std::uint32_t entity, std::uint64_t fingerprint) {
  fmt::format_to(std::back_inserter(buffer_), "{} {} {} {} {:016x}\n", index, t.ns(), kind, entity,
                 fingerprint);
  ++records_;
  last_fingerprint_ = fingerprint;
  if (buffer_.size() >= kFlushBytes) flush_buffer();
}

void TraceWriter::flush_buffer() {
  file_.stream().write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

void TraceWriter::commit() {
  fmt::format_to(std::back_inserter(buffer_), "end {} {:016x}\n", records_, last_fingerprint_);
  flush_buffer();
  file_.commit();
}

TraceReader::TraceReader(std::filesystem::path path) : path_(std::move(path)), in_(path_) {
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec))
    throw TraceFormatError(path_.string() +
                           ": is a directory, not a trace (covsim run --trace FILE writes one)");
  if (!in_) throw TraceFormatError(path_.string() + ": cannot open trace");
  std::string line;
  auto next_line = [&]() -> bool {
    if (!read_line(line)) return false;
    ++line_;
    return true;
  };
  if (!next_line() || line.rfind(std::string(kMagic) + " ", 0) != 0) {
    fail("expected '" + std::string(kMagic) + " <version>' on the first line");
  }
  const std::string version = line.substr(kMagic.size() + 1);
  if (version != "1")
    fail("unsupported trace format version '" + version + "' (this reader knows 1)");
  bool have_seed = false, have_hash = false;
  for (;;) {
    if (!next_line()) fail("header ends without an 'events' line");
    if (line == "events") break;
    const auto space = line.find(' ');
    if (space == std::string::npos) fail("expected '<key> <value>' in the header");
    std::string key = line.substr(0, space);
    std::string value = line.substr(space + 1);
    // A key twice would leave which value counts to the reader: refused.
    const bool repeated = (key == "seed" && have_seed) || (key == "scenario_hash" && have_hash) ||
                          std::any_of(header_.entries.begin(), header_.entries.end(),
                                      [&](const auto& entry) { return entry.first == key; });
    if (repeated) fail("the header has '" + key + "' twice");
    if (key == "seed") {
      auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), header_.seed);
      if (ec != std::errc() || p != value.data() + value.size())
        fail("seed is not an unsigned integer");
      have_seed = true;
    } else if (key == "scenario_hash") {
      auto h = Fingerprint::parse_hex(value);
      if (!h) fail("scenario_hash is not 16 hex digits");
      header_.scenario_hash = *h;
      have_hash = true;
    } else {
      header_.entries.emplace_back(std::move(key), std::move(value));
    }
  }
  if (!have_seed || !have_hash) fail("header lacks 'seed' or 'scenario_hash'");
}

bool TraceReader::read_line(std::string& line) {
  try {
    return read_bounded_line(in_, line, kMaxLineBytes, path_.string());
  } catch (const InputReadError&) {
    ++line_;
    fail("a line longer than any record (the file is not a trace)");
  }
}

void TraceReader::fail(const std::string& what) const {
  throw TraceFormatError(path_.string() + ":" + std::to_string(line_) + ": " + what);
}

std::optional<TraceRecord> TraceReader::next() {
  if (ended_) return std::nullopt;
  std::string line;
  if (!read_line(line))
    fail(fmt::format("the trace is cut short: it ends after {} events without its end record",
                     records_));
  ++line_;
  if (line.rfind("end ", 0) == 0) {
    std::uint64_t count = 0;
    const char* p = line.data() + 4;
    const char* end = line.data() + line.size();
    const auto [q, ec] = std::from_chars(p, end, count);
    const auto fp =
        q < end && *q == ' ' ? Fingerprint::parse_hex(std::string_view(q + 1, end)) : std::nullopt;
    if (ec != std::errc() || !fp) fail("malformed end record");
    if (count != records_ || (records_ > 0 && *fp != last_fingerprint_))
      fail(fmt::format(
          "the end record counts {} events ending at {}, the trace holds {} ending at "
          "{}: the trace was edited",
          count, Fingerprint::to_hex(*fp), records_, Fingerprint::to_hex(last_fingerprint_)));
    std::string rest;
    if (read_line(rest)) {
      ++line_;
      fail("text after the end record");
    }
    ended_ = true;
    return std::nullopt;
  }
  TraceRecord r;
  const char* p = line.data();
  const char* end = line.data() + line.size();
  auto field = [&](auto& out) {
    auto [q, ec] = std::from_chars(p, end, out);
    if (ec != std::errc() || (q != end && *q != ' ')) fail("malformed event record");
    p = (q == end) ? q : q + 1;
  };
  std::int64_t ns = 0;
  field(r.index);
  // Records are numbered in order from 0: another number means an edited trace, which
  // would otherwise show as a divergence between records that print the same.
  if (r.index != records_)
    fail(fmt::format("event record {} is numbered {}: the trace was edited", records_, r.index));
  field(ns);
  r.time = SimTime::from_ns(ns);
  const char* kind_end = std::find(p, end, ' ');
  if (kind_end == p || kind_end == end) fail("malformed event record");
  r.kind.assign(p, kind_end);
  p = kind_end + 1;
  field(r.entity);
  auto fp = Fingerprint::parse_hex(std::string_view(p, static_cast<std::size_t>(end - p)));
  if (!fp) fail("event record's fingerprint is not 16 hex digits");
  r.fingerprint = *fp;
  ++records_;
  last_fingerprint_ = r.fingerprint;
  return r;
}

std::optional<TraceDivergence> first_divergence(TraceReader& a, TraceReader& b) {
  for (std::uint64_t i = 0;; ++i) {
    std::optional<TraceRecord> ra = a.next();
    std::optional<TraceRecord> rb = b.next();
    if (!ra && !rb) return std::nullopt;
    if (ra != rb) return TraceDivergence{i, std::move(ra), std::move(rb)};
  }
}

}  // namespace covsim
