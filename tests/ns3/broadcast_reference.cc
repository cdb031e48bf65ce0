// SPDX-License-Identifier: GPL-2.0-or-later
// The ns3_wifi channel's reference: the same radios and broadcast schedule as a covsim run of
// robots held still, written as a plain ns-3 program (no covsim, no co-simulation), so that
// the coupling can be checked against ns-3 alone (tests/ns3/validation.sh).
//   broadcast_reference POSITIONS_FILE PERIOD_S DURATION_S BYTES RUN
// POSITIONS_FILE: one "x y" line per robot. Each robot broadcasts BYTES every PERIOD_S from a
// uniformly random phase in [0, PERIOD_S) until DURATION_S; 802.11b at 1 Mbit/s, ns-3's
// default log-distance loss and transmit power. Prints the delivery ratio (receptions over
// broadcasts × (robots - 1), counting broadcasts sent before DURATION_S) and the mean
// latency of the receptions by DURATION_S.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <vector>

#include "ns3/core-module.h"
#include "ns3/mobility-module.h"
#include "ns3/network-module.h"
#include "ns3/propagation-module.h"
#include "ns3/wifi-module.h"

using namespace ns3;

namespace {

std::uint64_t broadcasts = 0, receptions = 0;
double latency_sum = 0;
std::uint32_t bytes = 0;
double duration = 0;

bool received(Ptr<NetDevice>, Ptr<const Packet> packet, std::uint16_t, const Address&) {
  std::int64_t sent_ns = 0;
  packet->CopyData(reinterpret_cast<std::uint8_t*>(&sent_ns), sizeof sent_ns);
  if (Simulator::Now().GetSeconds() <= duration) {
    ++receptions;
    latency_sum += (Simulator::Now() - NanoSeconds(sent_ns)).GetSeconds();
  }
  return true;
}

void broadcast(Ptr<NetDevice> device, Time period) {
  std::vector<std::uint8_t> data(bytes, 0);
  const std::int64_t now = Simulator::Now().GetNanoSeconds();
  std::copy_n(reinterpret_cast<const std::uint8_t*>(&now), sizeof now, data.begin());
  device->Send(Create<Packet>(data.data(), bytes), device->GetBroadcast(), 0x88B5);
  ++broadcasts;
  if ((Simulator::Now() + period).GetSeconds() < duration)
    Simulator::Schedule(period, &broadcast, device, period);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: broadcast_reference POSITIONS_FILE PERIOD_S DURATION_S BYTES RUN\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::vector<Vector> positions;
  for (double x, y; in >> x >> y;)
    positions.emplace_back(x, y, 0.0);
  const Time period = Seconds(std::atof(argv[2]));
  duration = std::atof(argv[3]);
  bytes = static_cast<std::uint32_t>(std::atoi(argv[4]));
  RngSeedManager::SetSeed(1);
  RngSeedManager::SetRun(std::strtoull(argv[5], nullptr, 10));

  NodeContainer nodes;
  nodes.Create(positions.size());
  YansWifiChannelHelper channel = YansWifiChannelHelper::Default();  // log-distance, 3
  YansWifiPhyHelper phy;
  phy.SetChannel(channel.Create());
  WifiHelper wifi;
  wifi.SetStandard(WIFI_STANDARD_80211b);
  wifi.SetRemoteStationManager("ns3::ConstantRateWifiManager", "DataMode",
                               StringValue("DsssRate1Mbps"), "NonUnicastMode",
                               StringValue("DsssRate1Mbps"));
  WifiMacHelper mac;
  mac.SetType("ns3::AdhocWifiMac");
  NetDeviceContainer devices = wifi.Install(phy, mac, nodes);
  MobilityHelper mobility;
  mobility.SetMobilityModel("ns3::ConstantPositionMobilityModel");
  mobility.Install(nodes);
  Ptr<UniformRandomVariable> phase = CreateObject<UniformRandomVariable>();
  for (std::uint32_t i = 0; i < nodes.GetN(); ++i) {
    nodes.Get(i)->GetObject<MobilityModel>()->SetPosition(positions[i]);
    devices.Get(i)->SetReceiveCallback(MakeCallback(&received));
    Simulator::Schedule(Seconds(phase->GetValue(0.0, period.GetSeconds())), &broadcast,
                        devices.Get(i), period);
  }
  Simulator::Stop(Seconds(duration));
  Simulator::Run();
  Simulator::Destroy();
  const double links = static_cast<double>(broadcasts) * (positions.size() - 1);
  std::cout << "delivery_ratio " << receptions / links << "\n"
            << "latency_mean " << latency_sum / static_cast<double>(receptions) << "\n";
  return 0;
}
