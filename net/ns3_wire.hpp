// SPDX-License-Identifier: GPL-2.0-or-later
// (This header alone is also under GPL-2.0-or-later, so that the ns-3 peer, which links ns-3's
// GPL-2.0-only libraries, may include it; the rest of covsim is GPL-3.0-or-later.)
#pragma once
// The wire protocol between covsim and its ns-3 co-simulation peer (ns3peer/), version 1.
// Plain C++17 and the standard library only: both sides compile it. docs/ns3.md describes it.
//
// A frame is a little-endian header {u32 type, u32 payload length} and its payload. covsim
// writes to the peer's standard input, the peer to its standard output; every request has
// exactly one answer, so neither side ever waits for anything but the answer it asked for.
//
//   covsim -> peer                              peer -> covsim
//   hello    {u32 version, config text}         ready   {u32 version}
//   step     {i64 until_ns, u32 moves,          arrived {i64 until_ns, u32 count,
//             moves x {u32 robot, f64 x, f64 y},          count x {i64 at_ns, u32 receiver,
//             u32 sends,                                           u32 sender, u64 seq}}
//             sends x {u32 sender, u64 seq,
//                      u32 bytes, i64 at_ns}}
//   query    {}                                 stats   {u64 x 4, f64 x 2} (PeerStats)
//                                               error   {text}: the peer's last word
//
// The peer exits (status 0) when its input ends: covsim closes it at the end of a run.
// step: the moves take place at the peer's current time (the until_ns of the previous step, 0
// at first), in the order given; then the previous step's sends at its until_ns, then this
// step's sends, each at its at_ns (from the current time to until_ns; sends of one time in
// the order given; those at until_ns are made at the start of the next step, after its
// moves, as covsim moves its robots before they broadcast at one instant); the peer then
// runs its simulator through its events up to until_ns and answers with the receptions they
// made, in the order they happened. An event the run schedules for exactly until_ns itself runs in
// the next step, so a reception may carry the previous step's until_ns (never an earlier time). The
// config text is "key value" lines (docs/ns3.md lists the keys).
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace covsim::ns3wire {

inline constexpr std::uint32_t kVersion = 1;

enum class FrameType : std::uint32_t {
  hello = 0x484c4c4f,    // "HLLO"
  ready = 0x52454459,    // "REDY"
  step = 0x53544550,     // "STEP"
  arrived = 0x41525256,  // "ARRV"
  query = 0x51455259,    // "QERY"
  stats = 0x53544154,    // "STAT"
  error = 0x4552524f,    // "ERRO"
};

// The most a frame's payload may hold: a step of a million robots' moves is under 20 MB.
inline constexpr std::uint32_t kMaxPayload = 64u << 20;

struct Move {
  std::uint32_t robot;
  double x, y;
};
struct Send {
  std::uint32_t sender;
  std::uint64_t seq;
  std::uint32_t bytes;  // the message's size on the air, above the MAC
  std::int64_t at_ns;   // when it is sent
};
struct Arrival {
  std::int64_t at_ns;
  std::uint32_t receiver, sender;
  std::uint64_t seq;
};
struct PeerStats {
  std::uint64_t transmissions = 0;  // frames put on the air (PHY transmit starts)
  std::uint64_t receptions = 0;     // frames received whole (PHY receive ends, OK)
  std::uint64_t phy_drops = 0;      // receptions that began and failed (PHY drop trace)
  std::uint64_t mac_drops = 0;      // frames dropped before the air (MAC queue full or stale)
  double busy_seconds = 0;          // summed over robots: time each radio sensed the air busy
  double elapsed_seconds = 0;       // the peer's simulated time when asked
};

// Values on the wire are little-endian whatever the host: integers byte by byte, a double as
// its IEEE 754 bits.
static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559);

template <class T>
std::uint64_t bits_of(T value) {
  static_assert(std::is_integral_v<T> || std::is_same_v<T, double>);
  if constexpr (std::is_same_v<T, double>) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
  } else {
    return static_cast<std::uint64_t>(value);
  }
}

template <class T>
void put(std::string& out, T value) {
  const std::uint64_t bits = bits_of(value);
  for (std::size_t k = 0; k < sizeof(T); ++k)
    out.push_back(static_cast<char>((bits >> (8 * k)) & 0xff));
}

// Reads from a payload; `ok` turns false (and stays so) past its end.
class Reader {
 public:
  Reader(const char* data, std::size_t size) : p_(data), end_(data + size) {}
  template <class T>
  T get() {
    if (static_cast<std::size_t>(end_ - p_) < sizeof(T)) {
      ok_ = false;
      p_ = end_;
      return T{};
    }
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < sizeof(T); ++k)
      bits |= std::uint64_t{static_cast<unsigned char>(p_[k])} << (8 * k);
    p_ += sizeof(T);
    if constexpr (std::is_same_v<T, double>) {
      double value;
      std::memcpy(&value, &bits, sizeof value);
      return value;
    } else {
      return static_cast<T>(bits);
    }
  }
  std::string rest() {
    std::string s(p_, end_);
    p_ = end_;
    return s;
  }
  std::size_t left() const { return static_cast<std::size_t>(end_ - p_); }
  bool ok() const { return ok_; }

 private:
  const char* p_;
  const char* end_;
  bool ok_ = true;
};

// A frame's header {u32 type, u32 length}, as read from its 8 bytes.
struct FrameHeader {
  std::uint32_t type, length;
};
inline FrameHeader frame_header(const char (&bytes)[8]) {
  Reader r(bytes, 8);
  const auto type = r.get<std::uint32_t>();
  return FrameHeader{type, r.get<std::uint32_t>()};
}

inline std::string frame(FrameType type, const std::string& payload) {
  std::string out;
  put(out, static_cast<std::uint32_t>(type));
  put(out, static_cast<std::uint32_t>(payload.size()));
  return out + payload;
}

}  // namespace covsim::ns3wire
