#pragma once
// The ns3_wifi channel model: an 802.11 ad hoc network simulated by ns-3 in a peer program
// (covsim-ns3-peer, ns3peer/), one radio per robot. Broadcasts have the sizes covsim gives
// them, radios move with the robots, and a message arrives when and where ns-3 says: after
// the MAC's contention and backoff, and not at all after a collision or a fade. The path
// loss is ns-3's log-distance, Friis or range model, with a loss per wall passed (Ω's
// boundary, counted by the peer from the edges covsim sends) and Nakagami fading on top.
// See docs/ns3.md.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "net/channel_model.hpp"

namespace covsim {

struct Ns3WifiConfig {
  std::string standard = "b";
  std::string rate;           // an ns-3 WifiMode name (the scenario's, or the standard's lowest)
  double tx_power = 16.0206;  // dBm, ns-3's default
  std::string propagation = "log_distance";
  double exponent = 3.0, reference_loss = 46.6777, reference_distance = 1.0;
  double max_range = 250.0;
  std::string fading = "none";
  double nakagami_m = 1.0;
  double wall_loss = 5.0;  // dB per wall
};

// The "key value" lines of the hello frame (net/ns3_wire.hpp) for a run.
std::string ns3_peer_config_text(const Ns3WifiConfig& config, const ChannelContext& context);

// Where covsim looks for the peer program, in order: for a program running from the build
// tree, the peer built there and then the installed one; for any other, the installed one
// first. Empty when covsim was built without ns-3.
std::vector<std::filesystem::path> ns3_peer_candidates();
// $COVSIM_NS3_PEER as given if set, else the first candidate that exists; nullopt if none.
std::optional<std::filesystem::path> ns3_peer_program();

ChannelEntry ns3_wifi_channel_entry();

}  // namespace covsim
