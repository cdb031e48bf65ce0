#pragma once
// A run's fingerprint: a running 64-bit hash over every dispatched event's (time, kind,
// entity) and, at checkpoints, the bit patterns of chosen state. Two runs with the same
// fingerprint dispatched the same events in the same order and passed the same states.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/hash.hpp"
#include "core/sim_time.hpp"

namespace covsim {

class Fingerprint {
 public:
  std::uint64_t value() const { return h_; }
  void fold(std::uint64_t word) { h_ = hash_combine(h_, word); }
  // Called for every event, hence inline.
  void fold_event(SimTime t, std::uint64_t kind_key, std::uint32_t entity) {
    fold(static_cast<std::uint64_t>(t.ns()));
    // One round for kind and entity together: kind keys are 64-bit name hashes, so two
    // (kind, entity) pairs collide only by chance.
    fold(kind_key ^ (entity * 0xd6e8feb86659fd93ULL));
  }
  // Exact bit patterns: -0.0 and 0.0 differ, as they may lead to different results.
  void fold_state(double x);
  void fold_state(std::span<const double> xs);

  std::string hex() const { return to_hex(h_); }
  static std::string to_hex(std::uint64_t v);  // 16 lower-case hex digits
  static std::optional<std::uint64_t> parse_hex(std::string_view text);

 private:
  std::uint64_t h_ = 0x6a09e667f3bcc908ULL;
};

}  // namespace covsim
