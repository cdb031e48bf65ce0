// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// A propagation loss in dB for every wall a link passes through: the straight segment between
// the two radios is cut against Ω's boundary edges (covsim sends them), and each passage
// through an obstacle (into it and out again: two edges crossed) counts as one wall.
#include <vector>

#include "ns3/propagation-loss-model.h"

#include "peer_config.h"

namespace covsim_peer {

class WallLossModel : public ns3::PropagationLossModel {
 public:
  static ns3::TypeId GetTypeId();
  void SetWalls(std::vector<Wall> walls, double loss_db);
  // Walls between a and b: boundary edges properly crossed, halved (rounded up: a link that
  // ends on the far side of a single edge still went through a wall).
  int WallsBetween(double ax, double ay, double bx, double by) const;

 private:
  double DoCalcRxPower(double txPowerDbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t) override { return 0; }
  std::vector<Wall> walls_;
  double loss_db_ = 0;
};

}  // namespace covsim_peer
