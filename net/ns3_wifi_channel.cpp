#include "net/ns3_wifi_channel.hpp"

#include <fmt/format.h>

#include <fmt/ranges.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "net/ns3_wire.hpp"
#include "net/peer_process.hpp"

namespace covsim {

namespace fs = std::filesystem;

namespace {

// The modes each standard's radios offer, by ns-3's names: a scenario's rate is checked here,
// at load, not by a peer that aborts on a name it does not know.
const std::vector<std::string>& modes_of(const std::string& standard) {
  static const std::vector<std::string> b{"DsssRate1Mbps", "DsssRate2Mbps", "DsssRate5_5Mbps",
                                          "DsssRate11Mbps"};
  static const std::vector<std::string> g{
      "DsssRate1Mbps",     "DsssRate2Mbps",     "DsssRate5_5Mbps",   "DsssRate11Mbps",
      "ErpOfdmRate6Mbps",  "ErpOfdmRate9Mbps",  "ErpOfdmRate12Mbps", "ErpOfdmRate18Mbps",
      "ErpOfdmRate24Mbps", "ErpOfdmRate36Mbps", "ErpOfdmRate48Mbps", "ErpOfdmRate54Mbps"};
  static const std::vector<std::string> a{"OfdmRate6Mbps",  "OfdmRate9Mbps",  "OfdmRate12Mbps",
                                          "OfdmRate18Mbps", "OfdmRate24Mbps", "OfdmRate36Mbps",
                                          "OfdmRate48Mbps", "OfdmRate54Mbps"};
  static const std::vector<std::string> n{"HtMcs0", "HtMcs1", "HtMcs2", "HtMcs3",
                                          "HtMcs4", "HtMcs5", "HtMcs6", "HtMcs7"};
  return standard == "b" ? b : standard == "g" ? g : standard == "a" ? a : n;
}

// The rate of a scenario without one: the standard's lowest mandatory mode (for g the lowest
// ERP-OFDM one, not the DSSS modes g also offers).
std::string lowest_mode(const std::string& standard) {
  return standard == "g" ? "ErpOfdmRate6Mbps" : modes_of(standard).front();
}

// Longest wait for one answer of the peer: a step of a busy channel with a hundred radios
// takes well under a second.
constexpr double kAnswerTimeout = 120.0;

class Ns3WifiSession final : public ChannelSession {
 public:
  Ns3WifiSession(const fs::path& program, const std::string& config, std::size_t radios)
      : peer_(program, {}, kAnswerTimeout), radios_(static_cast<double>(radios)) {
    // Every frame sent, for `covsim-ns3-peer --replay FILE` (ns-3 alone with this traffic).
    if (const char* file = std::getenv("COVSIM_NS3_RECORD"); file != nullptr && *file != '\0') {
      record_.open(file, std::ios::binary | std::ios::trunc);
      if (!record_)
        throw PeerError(std::string(file) + ": cannot open for writing (COVSIM_NS3_RECORD)");
    }
    std::string hello;
    ns3wire::put(hello, ns3wire::kVersion);
    send(ns3wire::FrameType::hello, hello + config);
    std::string payload;
    expect(ns3wire::FrameType::ready, payload);
    ns3wire::Reader r(payload.data(), payload.size());
    const auto version = r.get<std::uint32_t>();
    if (!r.ok() || version != ns3wire::kVersion)
      throw PeerError(fmt::format("{}: speaks protocol version {}, covsim {}", peer_.name(),
                                  version, ns3wire::kVersion));
  }

  void broadcast(std::uint32_t sender, std::uint64_t seq, std::uint32_t bytes,
                 SimTime at) override {
    ++sends_;
    ns3wire::put(send_bytes_, sender);
    ns3wire::put(send_bytes_, seq);
    ns3wire::put(send_bytes_, bytes);
    ns3wire::put(send_bytes_, at.ns());
  }

  void moved(std::uint32_t robot, Vec2 p) override {
    ++moves_;
    ns3wire::put(move_bytes_, robot);
    ns3wire::put(move_bytes_, p.x);
    ns3wire::put(move_bytes_, p.y);
  }

  void advance(SimTime t, std::vector<Reception>& out) override {
    std::string step;
    ns3wire::put(step, t.ns());
    ns3wire::put(step, moves_);
    step += move_bytes_;
    ns3wire::put(step, sends_);
    step += send_bytes_;
    moves_ = sends_ = 0;
    move_bytes_.clear();
    send_bytes_.clear();
    send(ns3wire::FrameType::step, step);
    std::string payload;
    expect(ns3wire::FrameType::arrived, payload);
    ns3wire::Reader r(payload.data(), payload.size());
    const auto until = r.get<std::int64_t>();
    const auto count = r.get<std::uint32_t>();
    if (!r.ok() || until != t.ns() || r.left() != std::size_t{count} * 24)
      throw PeerError(peer_.name() + ": a malformed answer to a step");
    for (std::uint32_t k = 0; k < count; ++k) {
      Reception rec;
      rec.at = SimTime::from_ns(r.get<std::int64_t>());
      rec.receiver = r.get<std::uint32_t>();
      rec.sender = r.get<std::uint32_t>();
      rec.seq = r.get<std::uint64_t>();
      if (rec.at > t || rec.at < last_)
        throw PeerError(fmt::format("{}: a reception at {} s, outside the step from {} to {} s",
                                    peer_.name(), rec.at.seconds(), last_.seconds(), t.seconds()));
      out.push_back(rec);
    }
    last_ = t;
  }

  RadioTotals totals() override {
    send(ns3wire::FrameType::query, {});
    std::string payload;
    expect(ns3wire::FrameType::stats, payload);
    ns3wire::Reader r(payload.data(), payload.size());
    ns3wire::PeerStats s;
    s.transmissions = r.get<std::uint64_t>();
    s.receptions = r.get<std::uint64_t>();
    s.phy_drops = r.get<std::uint64_t>();
    s.mac_drops = r.get<std::uint64_t>();
    s.busy_seconds = r.get<double>();
    s.elapsed_seconds = r.get<double>();
    if (!r.ok() || r.left() != 0) throw PeerError(peer_.name() + ": a malformed stats frame");
    RadioTotals out;
    out.transmissions = s.transmissions;
    out.phy_drops = s.phy_drops;
    out.mac_drops = s.mac_drops;
    out.occupancy =
        s.elapsed_seconds > 0 && radios_ > 0 ? s.busy_seconds / (s.elapsed_seconds * radios_) : 0.0;
    return out;
  }

 private:
  void send(ns3wire::FrameType type, const std::string& payload) {
    peer_.send(type, payload);
    if (record_.is_open()) {
      record_ << ns3wire::frame(type, payload);
      if (!record_)
        throw PeerError("cannot write the record of the peer's frames (COVSIM_NS3_RECORD)");
    }
  }

  void expect(ns3wire::FrameType type, std::string& payload) {
    const std::uint32_t got = peer_.receive(payload);
    if (got != static_cast<std::uint32_t>(type))
      throw PeerError(fmt::format("{}: answered with a frame of type {:#x}, expected {:#x}",
                                  peer_.name(), got, static_cast<std::uint32_t>(type)));
  }

  PeerProcess peer_;
  std::ofstream record_;
  std::uint32_t moves_ = 0, sends_ = 0;
  std::string move_bytes_, send_bytes_;
  SimTime last_;
  double radios_;
};

class Ns3WifiChannel final : public ChannelModel {
 public:
  explicit Ns3WifiChannel(Ns3WifiConfig c) : config_(std::move(c)) {}
  std::unique_ptr<ChannelSession> open(const ChannelContext& context) const override {
    const auto program = ns3_peer_program();
    if (!program) {
      const std::vector<fs::path> looked = ns3_peer_candidates();
      if (looked.empty())
        throw PeerError(
            "the ns3_wifi channel is unavailable: covsim was built without ns-3 (install "
            "libns3-dev, ns3 and libgsl-dev and build again, or set COVSIM_NS3_PEER)");
      std::vector<std::string> names;
      for (const fs::path& p : looked)
        names.push_back(p.string());
      throw PeerError(
          fmt::format("the ns3_wifi channel's peer program is missing (looked for {}): build the "
                      "covsim-ns3-peer target, or set COVSIM_NS3_PEER",
                      fmt::join(names, " and ")));
    }
    return std::make_unique<Ns3WifiSession>(*program, ns3_peer_config_text(config_, context),
                                            context.positions.size());
  }
  std::vector<std::string> replaces() const override {
    return {"range", "line_of_sight", "loss", "delay"};
  }

 private:
  Ns3WifiConfig config_;
};

}  // namespace

std::string ns3_peer_config_text(const Ns3WifiConfig& c, const ChannelContext& context) {
  std::string out = fmt::format("robots {}\nrun {}\nstandard {}\n", context.positions.size(),
                                context.seed, c.standard);
  out += fmt::format("rate {}\n", c.rate);
  // Shortest round-trip text for every number: the peer reads the doubles covsim holds.
  out += fmt::format("tx_power_dbm {}\npropagation {}\n", c.tx_power, c.propagation);
  out += fmt::format("exponent {}\nreference_loss_db {}\nreference_distance {}\nmax_range {}\n",
                     c.exponent, c.reference_loss, c.reference_distance, c.max_range);
  if (c.fading == "nakagami") out += fmt::format("nakagami_m {}\n", c.nakagami_m);
  out += fmt::format("wall_loss_db {}\n", c.wall_loss);
  for (const auto& ring : context.env.rings()) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      out += fmt::format("wall {} {} {} {}\n", a.x, a.y, b.x, b.y);
    }
  }
  for (std::size_t i = 0; i < context.positions.size(); ++i)
    out += fmt::format("position {} {} {}\n", i, context.positions[i].x, context.positions[i].y);
  return out;
}

std::vector<fs::path> ns3_peer_candidates() {
  std::vector<fs::path> out;
#ifdef COVSIM_NS3_PEER_BUILT
  // A program in the build tree uses the peer built beside it; any other (installed, or a
  // user's linking the installed library) the installed peer first.
  std::error_code ec;
  const std::string self = fs::read_symlink("/proc/self/exe", ec).string();
  const std::string build_dir = COVSIM_BUILD_DIR;
  const bool in_build = !ec && self.compare(0, build_dir.size() + 1, build_dir + "/") == 0;
  if (in_build) out.emplace_back(COVSIM_NS3_PEER_BUILT);
  out.emplace_back(COVSIM_NS3_PEER_INSTALLED);
  if (!in_build) out.emplace_back(COVSIM_NS3_PEER_BUILT);
#endif
  return out;
}

std::optional<fs::path> ns3_peer_program() {
  if (const char* env = std::getenv("COVSIM_NS3_PEER"); env != nullptr && *env != '\0')
    return fs::path(env);  // as given: a wrong one is the run's error, naming it
  for (const fs::path& p : ns3_peer_candidates()) {
    std::error_code ec;
    if (fs::exists(p, ec)) return p;
  }
  return std::nullopt;
}

ChannelEntry ns3_wifi_channel_entry() {
  ChannelEntry e;
  e.name = "ns3_wifi";
  e.description =
      "802.11 ad hoc radios simulated by ns-3 (a co-simulation peer): contention, collisions, "
      "path loss, walls and fading";
  const Ns3WifiConfig d;
  e.params = {
      ParamSpec::choice("standard", {"b", "g", "a", "n"}, "802.11 amendment")
          .defaults_to(d.standard),
      ParamSpec::text("rate",
                      "ns-3 WifiMode of every broadcast (802.11 broadcasts are not "
                      "acknowledged, so no rate manager adapts them); null: the standard's "
                      "lowest (DsssRate1Mbps, ErpOfdmRate6Mbps, OfdmRate6Mbps, HtMcs0)")
          .or_null()
          .defaults_to(std::monostate{}),
      ParamSpec::number("tx_power", "dBm", "transmit power")
          .at_least(-50)
          .at_most(40)
          .defaults_to(d.tx_power),
      ParamSpec::choice("propagation", {"log_distance", "friis", "range"}, "ns-3's path loss model")
          .defaults_to(d.propagation),
      ParamSpec::number("exponent", "", "log_distance: the path loss exponent")
          .at_least(1)
          .at_most(10)
          .defaults_to(d.exponent),
      ParamSpec::number("reference_loss", "dB", "log_distance: the loss at the reference distance")
          .at_least(0)
          .at_most(200)
          .defaults_to(d.reference_loss),
      ParamSpec::number("reference_distance", "m", "log_distance: the reference distance")
          .positive()
          .defaults_to(d.reference_distance),
      ParamSpec::number("max_range", "m", "range: every radio within it hears, none beyond")
          .positive()
          .defaults_to(d.max_range),
      ParamSpec::choice("fading", {"none", "nakagami"}, "fading on top of the path loss")
          .defaults_to(d.fading),
      ParamSpec::number("nakagami_m", "", "nakagami: the shape m (1: Rayleigh)")
          .at_least(0.5)
          .at_most(100)
          .defaults_to(d.nakagami_m),
      ParamSpec::number("wall_loss", "dB",
                        "loss for each wall the straight link passes through (an obstacle of "
                        "Ω, or the outer boundary folded across it)")
          .at_least(0)
          .at_most(200)
          .defaults_to(d.wall_loss),
  };
  e.make = [](const Params& p) -> std::shared_ptr<const ChannelModel> {
    Ns3WifiConfig c;
    c.standard = p.text("standard");
    c.rate = p.has("rate") ? p.text("rate") : lowest_mode(c.standard);
    const auto& modes = modes_of(c.standard);
    if (std::find(modes.begin(), modes.end(), c.rate) == modes.end())
      throw ParamError("rate", fmt::format("802.11{} has no mode \"{}\" (expected one of {})",
                                           c.standard, c.rate, fmt::join(modes, ", ")));
    c.tx_power = p.number("tx_power");
    c.propagation = p.text("propagation");
    c.exponent = p.number("exponent");
    c.reference_loss = p.number("reference_loss");
    c.reference_distance = p.number("reference_distance");
    c.max_range = p.number("max_range");
    c.fading = p.text("fading");
    c.nakagami_m = p.number("nakagami_m");
    c.wall_loss = p.number("wall_loss");
    return std::make_shared<const Ns3WifiChannel>(std::move(c));
  };
  return e;
}

}  // namespace covsim
