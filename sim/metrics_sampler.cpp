#include "sim/metrics_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "robot/mapping.hpp"

namespace covsim {

void MetricsSampler::on_sample(SimTime t, const CoverageController& controller) {
  if (!network_) network_ = std::make_unique<NetworkMetrics>(controller.environment());
  MetricsSample s;
  s.t = t.seconds();
  const VoronoiPartition& vp = controller.virtual_partition();
  s.cost_virtual = vp.cost();
  s.cost_real_in_virtual_partition = vp.cost(controller.positions());
  s.cost_real = controller.real_partition().cost();
  for (const Robot& r : controller.robots()) {
    s.settled += is_settled(r.status) ? 1 : 0;
    s.projected += r.projected ? 1 : 0;
    s.path_length += r.path_length;
  }
  s.messages = controller.network_totals();
  s.network = network_->sample(controller);
  if (const Mapping* m = controller.mapping()) {
    s.known_fraction = m->known_fraction();
    for (std::uint32_t i = 0; i < controller.robots().size(); ++i)
      s.known_fraction_min = std::min(s.known_fraction_min, m->known_fraction(i));
    s.map_disagreement = m->disagreement();
  }
  samples_.push_back(s);
}

void MetricsSampler::on_finish(SimTime t, const CoverageController& c) {
  if (samples_.empty() || samples_.back().t < t.seconds()) on_sample(t, c);
}

CommunicationSummary summarize_communication(const std::vector<MetricsSample>& samples) {
  CommunicationSummary out;
  if (samples.empty()) return out;
  double connected = 0.0;
  // NaN unless some sample computed it.
  out.algebraic_connectivity_min = std::numeric_limits<double>::quiet_NaN();
  for (const MetricsSample& s : samples) {
    out.info_age_mean += s.network.info_age_mean;
    out.info_age_max = std::max(out.info_age_max, s.network.info_age_max);
    out.area_claimed_by_none += s.network.area_claimed_by_none;
    out.area_claimed_by_several += s.network.area_claimed_by_several;
    connected += s.network.graph.components <= 1 ? 1.0 : 0.0;
    const double a = s.network.graph.algebraic_connectivity;
    if (!std::isnan(a) && !(a >= out.algebraic_connectivity_min))
      out.algebraic_connectivity_min = a;
  }
  const auto n = static_cast<double>(samples.size());
  out.info_age_mean /= n;
  out.area_claimed_by_none /= n;
  out.area_claimed_by_several /= n;
  out.connected_fraction = connected / n;
  return out;
}

}  // namespace covsim
