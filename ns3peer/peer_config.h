// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// The radio a covsim run asks for, as the hello frame's "key value" lines (docs/ns3.md).
#include <cstdint>
#include <string>
#include <vector>

namespace covsim_peer {

struct Wall {
  double x1, y1, x2, y2;
};

struct PeerConfig {
  std::uint32_t robots = 0;
  std::uint64_t run = 1;                     // ns-3's RngRun: the covsim run's seed
  std::string standard = "b";                // 802.11 b, g, a or n
  std::string rate;                          // an ns-3 WifiMode name (covsim always gives one)
  double tx_power_dbm = 16.0206;             // ns-3's default
  std::string propagation = "log_distance";  // log_distance, friis or range
  double exponent = 3.0, reference_loss_db = 46.6777, reference_distance = 1.0;
  double max_range = 250.0;  // "range" only
  double nakagami_m = 0.0;   // > 0: Nakagami fading with this shape on top
  double wall_loss_db = 0.0;
  std::vector<Wall> walls;   // Ω's boundary edges
  std::vector<double> x, y;  // the robots' starting positions
};

// Throws std::invalid_argument naming the line at fault.
PeerConfig parse_peer_config(const std::string& text);

}  // namespace covsim_peer
