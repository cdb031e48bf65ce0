// SPDX-License-Identifier: GPL-2.0-or-later
#include "wall_loss_model.h"

#include "ns3/mobility-model.h"

namespace covsim_peer {

ns3::TypeId WallLossModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("covsim::WallLossModel")
                               .SetParent<ns3::PropagationLossModel>()
                               .AddConstructor<WallLossModel>();
  return tid;
}

void WallLossModel::SetWalls(std::vector<Wall> walls, double loss_db) {
  walls_ = std::move(walls);
  loss_db_ = loss_db;
}

namespace {
double cross(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}
}  // namespace

int WallLossModel::WallsBetween(double ax, double ay, double bx, double by) const {
  int crossings = 0;
  for (const Wall& w : walls_) {
    const double d1 = cross(ax, ay, bx, by, w.x1, w.y1);
    const double d2 = cross(ax, ay, bx, by, w.x2, w.y2);
    const double d3 = cross(w.x1, w.y1, w.x2, w.y2, ax, ay);
    const double d4 = cross(w.x1, w.y1, w.x2, w.y2, bx, by);
    // Proper crossings only: a link along an edge or through a vertex grazes, not passes.
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
      ++crossings;
  }
  return (crossings + 1) / 2;
}

double WallLossModel::DoCalcRxPower(double txPowerDbm, ns3::Ptr<ns3::MobilityModel> a,
                                    ns3::Ptr<ns3::MobilityModel> b) const {
  if (loss_db_ == 0 || walls_.empty()) return txPowerDbm;
  const ns3::Vector pa = a->GetPosition(), pb = b->GetPosition();
  return txPowerDbm - loss_db_ * WallsBetween(pa.x, pa.y, pb.x, pb.y);
}

}  // namespace covsim_peer
