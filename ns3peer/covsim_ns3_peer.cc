// SPDX-License-Identifier: GPL-2.0-or-later
// covsim-ns3-peer: the ns-3 side of covsim's ns3_wifi channel, a program of its own (ns-3 is
// GPL-2.0-only, covsim links GPL-3.0-or-later code: no binary may hold both). covsim starts
// it per run and drives it over its standard input and output with the frames of
// net/ns3_wire.hpp: one ad hoc 802.11 node per robot, broadcasts of the sizes covsim gives,
// positions as covsim moves the robots, and the receptions back with their times.
//
// covsim-ns3-peer --replay FILE: reads the frames from FILE instead (as covsim wrote them with
// COVSIM_NS3_RECORD=FILE) and answers none: ns-3 alone with a run's traffic.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "net/ns3_wire.hpp"
#include "ns3/core-module.h"
#include "ns3/mobility-module.h"
#include "ns3/network-module.h"
#include "ns3/propagation-module.h"
#include "ns3/wifi-module.h"
#include "peer_config.h"
#include "wall_loss_model.h"

namespace wire = covsim::ns3wire;
using covsim_peer::PeerConfig;

namespace {

constexpr std::uint16_t kProtocol = 0x88B5;  // IEEE 802 local experimental EtherType

struct PeerState {
  std::vector<ns3::Ptr<ns3::NetDevice>> devices;
  std::vector<ns3::Ptr<ns3::MobilityModel>> mobility;
  std::vector<wire::Arrival> arrivals;  // since the last answer
  std::vector<wire::Send> deferred;     // sends at the last step's end, made at the next
  wire::PeerStats stats;
};
PeerState peer;
int input = 0;          // the frames' source: standard input, or the replayed file
bool answering = true;  // false when replaying

bool read_all(void* data, std::size_t size) {
  auto* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = ::read(input, p, size);
    if (n == 0) return false;
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

void write_all(const std::string& bytes) {
  if (!answering) return;
  const char* p = bytes.data();
  std::size_t size = bytes.size();
  while (size > 0) {
    const ssize_t n = ::write(1, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) std::exit(1);  // covsim is gone
    p += n;
    size -= static_cast<std::size_t>(n);
  }
}

[[noreturn]] void fail(const std::string& what) {
  if (!answering) std::fprintf(stderr, "covsim-ns3-peer: %s\n", what.c_str());
  write_all(wire::frame(wire::FrameType::error, what));
  std::exit(1);
}

// The next frame; false at the end of the input (covsim closed it).
bool read_frame(wire::FrameType& type, std::string& payload) {
  char bytes[8];
  if (!read_all(bytes, sizeof bytes)) return false;
  const wire::FrameHeader header = wire::frame_header(bytes);
  if (header.length > wire::kMaxPayload) fail("a frame larger than the protocol allows");
  type = static_cast<wire::FrameType>(header.type);
  payload.resize(header.length);
  if (!read_all(payload.data(), payload.size())) fail("the input ends inside a frame");
  return true;
}

bool on_receive(ns3::Ptr<ns3::NetDevice> device, ns3::Ptr<const ns3::Packet> packet, std::uint16_t,
                const ns3::Address&) {
  std::uint8_t head[12];
  if (packet->CopyData(head, sizeof head) != sizeof head) return true;
  wire::Reader r(reinterpret_cast<const char*>(head), sizeof head);
  const auto sender = r.get<std::uint32_t>();
  const auto seq = r.get<std::uint64_t>();
  peer.arrivals.push_back(wire::Arrival{ns3::Simulator::Now().GetNanoSeconds(),
                                        device->GetNode()->GetId(), sender, seq});
  ++peer.stats.receptions;
  return true;
}

void on_tx_begin(ns3::Ptr<const ns3::Packet>, double) {
  ++peer.stats.transmissions;
}
void on_rx_drop(ns3::Ptr<const ns3::Packet>, ns3::WifiPhyRxfailureReason) {
  ++peer.stats.phy_drops;
}
// Frames the MAC gave up before the air: its queue full, or a frame older than its limit.
void on_mac_drop(ns3::WifiMacDropReason, ns3::Ptr<const ns3::WifiMpdu>) {
  ++peer.stats.mac_drops;
}
void on_state(ns3::Time, ns3::Time duration, WifiPhyState state) {
  if (state == WifiPhyState::TX || state == WifiPhyState::RX || state == WifiPhyState::CCA_BUSY)
    peer.stats.busy_seconds += duration.GetSeconds();
}

ns3::WifiStandard standard_of(const std::string& name) {
  if (name == "b") return ns3::WIFI_STANDARD_80211b;
  if (name == "g") return ns3::WIFI_STANDARD_80211g;
  if (name == "a") return ns3::WIFI_STANDARD_80211a;
  if (name == "n") return ns3::WIFI_STANDARD_80211n;
  fail("unknown 802.11 standard '" + name + "' (expected b, g, a or n)");
}

void build(const PeerConfig& c) {
  ns3::RngSeedManager::SetSeed(1);
  ns3::RngSeedManager::SetRun(c.run);
  ns3::NodeContainer nodes;
  nodes.Create(c.robots);

  ns3::Ptr<ns3::PropagationLossModel> loss;
  if (c.propagation == "log_distance") {
    auto m = ns3::CreateObject<ns3::LogDistancePropagationLossModel>();
    m->SetPathLossExponent(c.exponent);
    m->SetReference(c.reference_distance, c.reference_loss_db);
    loss = m;
  } else if (c.propagation == "friis") {
    auto m = ns3::CreateObject<ns3::FriisPropagationLossModel>();
    // 802.11b and g use the 2.4 GHz band (channel 1); a and n ns-3's default 5.15 GHz.
    if (c.standard == "b" || c.standard == "g") m->SetFrequency(2.412e9);
    loss = m;
  } else if (c.propagation == "range") {
    auto m = ns3::CreateObject<ns3::RangePropagationLossModel>();
    m->SetAttribute("MaxRange", ns3::DoubleValue(c.max_range));
    loss = m;
  } else {
    fail("unknown propagation model '" + c.propagation + "'");
  }
  ns3::Ptr<ns3::PropagationLossModel> last = loss;
  if (c.wall_loss_db > 0 && !c.walls.empty()) {
    auto walls = ns3::CreateObject<covsim_peer::WallLossModel>();
    walls->SetWalls(c.walls, c.wall_loss_db);
    last->SetNext(walls);
    last = walls;
  }
  if (c.nakagami_m > 0) {
    auto fading = ns3::CreateObject<ns3::NakagamiPropagationLossModel>();
    fading->SetAttribute("m0", ns3::DoubleValue(c.nakagami_m));
    fading->SetAttribute("m1", ns3::DoubleValue(c.nakagami_m));
    fading->SetAttribute("m2", ns3::DoubleValue(c.nakagami_m));
    last->SetNext(fading);
    last = fading;
  }
  auto channel = ns3::CreateObject<ns3::YansWifiChannel>();
  channel->SetPropagationLossModel(loss);
  channel->SetPropagationDelayModel(ns3::CreateObject<ns3::ConstantSpeedPropagationDelayModel>());

  ns3::YansWifiPhyHelper phy;
  phy.SetChannel(channel);
  phy.Set("TxPowerStart", ns3::DoubleValue(c.tx_power_dbm));
  phy.Set("TxPowerEnd", ns3::DoubleValue(c.tx_power_dbm));
  ns3::WifiHelper wifi;
  wifi.SetStandard(standard_of(c.standard));
  if (c.rate.empty()) fail("the config names no rate");
  const std::string& rate = c.rate;
  // Broadcasts are not acknowledged, so no rate manager can adapt them: they go at one mode.
  wifi.SetRemoteStationManager("ns3::ConstantRateWifiManager", "DataMode", ns3::StringValue(rate),
                               "ControlMode", ns3::StringValue(rate), "NonUnicastMode",
                               ns3::StringValue(rate));
  ns3::WifiMacHelper mac;
  mac.SetType("ns3::AdhocWifiMac");
  const ns3::NetDeviceContainer devices = wifi.Install(phy, mac, nodes);

  ns3::MobilityHelper mobility;
  mobility.SetMobilityModel("ns3::ConstantPositionMobilityModel");
  mobility.Install(nodes);
  // Fixed streams: the same draws whatever else ns-3 creates.
  const std::int64_t streams = wifi.AssignStreams(devices, 0);
  channel->AssignStreams(streams);

  for (std::uint32_t i = 0; i < c.robots; ++i) {
    ns3::Ptr<ns3::NetDevice> d = devices.Get(i);
    d->SetReceiveCallback(ns3::MakeCallback(&on_receive));
    auto wd = ns3::DynamicCast<ns3::WifiNetDevice>(d);
    wd->GetPhy()->TraceConnectWithoutContext("PhyTxBegin", ns3::MakeCallback(&on_tx_begin));
    wd->GetPhy()->TraceConnectWithoutContext("PhyRxDrop", ns3::MakeCallback(&on_rx_drop));
    wd->GetPhy()->GetState()->TraceConnectWithoutContext("State", ns3::MakeCallback(&on_state));
    wd->GetMac()->TraceConnectWithoutContext("DroppedMpdu", ns3::MakeCallback(&on_mac_drop));
    peer.devices.push_back(d);
    peer.mobility.push_back(nodes.Get(i)->GetObject<ns3::MobilityModel>());
    peer.mobility.back()->SetPosition(ns3::Vector(c.x[i], c.y[i], 0.0));
  }
}

void send(std::uint32_t sender, std::uint64_t seq, std::uint32_t bytes) {
  // The first 12 bytes name the message; the rest is the size covsim's message would have.
  std::string data;
  wire::put(data, sender);
  wire::put(data, seq);
  data.resize(std::max<std::size_t>(bytes, data.size()), '\0');
  auto packet = ns3::Create<ns3::Packet>(reinterpret_cast<const std::uint8_t*>(data.data()),
                                         static_cast<std::uint32_t>(data.size()));
  ns3::Ptr<ns3::NetDevice> d = peer.devices[sender];
  d->Send(packet, d->GetBroadcast(), kProtocol);
}

void step(const std::string& payload) {
  wire::Reader r(payload.data(), payload.size());
  const auto until = r.get<std::int64_t>();
  const auto moves = r.get<std::uint32_t>();
  if (!r.ok() || r.left() / 20 < moves) fail("a malformed step frame");
  for (std::uint32_t k = 0; k < moves; ++k) {
    const auto robot = r.get<std::uint32_t>();
    const double x = r.get<double>(), y = r.get<double>();
    if (robot >= peer.mobility.size()) fail("a move of an unknown robot");
    peer.mobility[robot]->SetPosition(ns3::Vector(x, y, 0.0));
  }
  // Sends deferred from the last step's end come now, after this step's moves: covsim moves
  // its robots before they broadcast at one instant.
  for (const wire::Send& d : peer.deferred)
    send(d.sender, d.seq, d.bytes);
  peer.deferred.clear();
  const auto sends = r.get<std::uint32_t>();
  if (!r.ok() || r.left() != std::size_t{sends} * 24) fail("a malformed step frame");
  const ns3::Time now = ns3::Simulator::Now();
  for (std::uint32_t k = 0; k < sends; ++k) {
    const auto sender = r.get<std::uint32_t>();
    const auto seq = r.get<std::uint64_t>();
    const auto bytes = r.get<std::uint32_t>();
    const auto at = r.get<std::int64_t>();
    if (sender >= peer.devices.size() || bytes > 2304) fail("a malformed send");
    if (at < now.GetNanoSeconds() || at > until) fail("a send outside the step");
    if (at == now.GetNanoSeconds())
      send(sender, seq, bytes);
    else if (at == until)
      peer.deferred.push_back(wire::Send{sender, seq, bytes, at});
    else
      ns3::Simulator::Schedule(ns3::NanoSeconds(at) - now, &send, sender, seq, bytes);
  }
  if (until < now.GetNanoSeconds()) fail("a step back in time");
  if (until > now.GetNanoSeconds()) {
    ns3::Simulator::Stop(ns3::NanoSeconds(until) - now);
    ns3::Simulator::Run();
  }
  std::string out;
  wire::put(out, until);
  wire::put(out, static_cast<std::uint32_t>(peer.arrivals.size()));
  for (const wire::Arrival& a : peer.arrivals) {
    wire::put(out, a.at_ns);
    wire::put(out, a.receiver);
    wire::put(out, a.sender);
    wire::put(out, a.seq);
  }
  peer.arrivals.clear();
  write_all(wire::frame(wire::FrameType::arrived, out));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--replay") {
    input = ::open(argv[2], O_RDONLY | O_CLOEXEC);
    answering = false;
    if (input < 0) {
      std::fprintf(stderr, "covsim-ns3-peer: cannot open %s\n", argv[2]);
      return 2;
    }
  } else if (argc != 1) {
    std::fprintf(stderr, "usage: covsim-ns3-peer [--replay FILE] (covsim starts it)\n");
    return 2;
  }
  try {
    wire::FrameType type{};
    std::string payload;
    if (!read_frame(type, payload)) return 0;
    if (type != wire::FrameType::hello) fail("expected a hello frame first");
    wire::Reader r(payload.data(), payload.size());
    const auto version = r.get<std::uint32_t>();
    if (!r.ok() || version != wire::kVersion)
      fail("covsim speaks protocol version " + std::to_string(version) + ", this peer " +
           std::to_string(wire::kVersion));
    build(covsim_peer::parse_peer_config(r.rest()));
    std::string ready;
    wire::put(ready, wire::kVersion);
    write_all(wire::frame(wire::FrameType::ready, ready));
    while (read_frame(type, payload)) {
      if (type == wire::FrameType::step) {
        step(payload);
      } else if (type == wire::FrameType::query) {
        peer.stats.elapsed_seconds = ns3::Simulator::Now().GetSeconds();
        std::string out;
        wire::put(out, peer.stats.transmissions);
        wire::put(out, peer.stats.receptions);
        wire::put(out, peer.stats.phy_drops);
        wire::put(out, peer.stats.mac_drops);
        wire::put(out, peer.stats.busy_seconds);
        wire::put(out, peer.stats.elapsed_seconds);
        write_all(wire::frame(wire::FrameType::stats, out));
      } else {
        fail("an unknown frame type");
      }
    }
    ns3::Simulator::Destroy();
    return 0;
  } catch (const std::exception& e) {
    fail(e.what());
  }
}
