// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// A propagation loss in dB for every wall a link passes through: the straight segment between
// the two radios is cut where it meets Ω's boundary edges (covsim sends them), and each run of
// pieces outside Ω (inside an obstacle, or beyond the outer boundary where it folds back)
// counts as one wall. A radio on a wall's face (a robot settled at a projection) still has
// the wall between it and a robot on the other side.
#include <vector>

#include "ns3/propagation-loss-model.h"

#include "peer_config.h"

namespace covsim_peer {

class WallLossModel : public ns3::PropagationLossModel {
 public:
  static ns3::TypeId GetTypeId();
  void SetWalls(std::vector<Wall> walls, double loss_db);
  // Walls between a and b: the runs of the segment's pieces whose middles lie outside Ω.
  int WallsBetween(double ax, double ay, double bx, double by) const;
  // Even-odd over every ring: inside the outer boundary and in no obstacle.
  bool InsideOmega(double x, double y) const;

 private:
  double DoCalcRxPower(double txPowerDbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t) override { return 0; }
  std::vector<Wall> walls_;
  double loss_db_ = 0;
};

}  // namespace covsim_peer
