// SPDX-License-Identifier: GPL-2.0-or-later
#include "wall_loss_model.h"

#include <algorithm>

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

int WallLossModel::WallsBetween(double ax, double ay, double bx, double by) const {
  // Where the segment meets the edges, as fractions of its length.
  std::vector<double> cuts{0.0, 1.0};
  const double dx = bx - ax, dy = by - ay;
  for (const Wall& w : walls_) {
    const double ex = w.x2 - w.x1, ey = w.y2 - w.y1;
    const double denom = dx * ey - dy * ex;
    if (denom == 0) continue;  // parallel: an overlap adds no passage of its own
    const double t = ((w.x1 - ax) * ey - (w.y1 - ay) * ex) / denom;
    const double u = ((w.x1 - ax) * dy - (w.y1 - ay) * dx) / denom;
    if (t > 0 && t < 1 && u >= 0 && u <= 1) cuts.push_back(t);
  }
  std::sort(cuts.begin(), cuts.end());
  int walls = 0;
  bool outside_before = false;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (cuts[k + 1] - cuts[k] <= 1e-12) continue;
    const double m = 0.5 * (cuts[k] + cuts[k + 1]);
    const bool outside = !InsideOmega(ax + m * dx, ay + m * dy);
    if (outside && !outside_before) ++walls;
    outside_before = outside;
  }
  return walls;
}

bool WallLossModel::InsideOmega(double x, double y) const {
  bool inside = false;
  for (const Wall& w : walls_) {
    if ((w.y1 > y) != (w.y2 > y) && x < w.x1 + (y - w.y1) / (w.y2 - w.y1) * (w.x2 - w.x1))
      inside = !inside;
  }
  return inside;
}

double WallLossModel::DoCalcRxPower(double txPowerDbm, ns3::Ptr<ns3::MobilityModel> a,
                                    ns3::Ptr<ns3::MobilityModel> b) const {
  if (loss_db_ == 0 || walls_.empty()) return txPowerDbm;
  const ns3::Vector pa = a->GetPosition(), pb = b->GetPosition();
  return txPowerDbm - loss_db_ * WallsBetween(pa.x, pa.y, pb.x, pb.y);
}

}  // namespace covsim_peer
