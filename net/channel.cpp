#include "net/channel.hpp"

#include <algorithm>
#include <cmath>

namespace covsim {

double GilbertElliottLoss::stationary_loss() const {
  const double s = p_good_to_bad + p_bad_to_good;
  const double bad = s > 0.0 ? p_good_to_bad / s : 0.0;
  return (1.0 - bad) * loss_good + bad * loss_bad;
}

double DistanceLoss::at(double d) const {
  return std::min(1.0, p_min + (1.0 - p_min) * std::pow(d / d_max, exponent));
}

double minimum_delay(const DelayModel& d) {
  return std::visit(
      [](const auto& m) -> double {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, ConstantDelay>) return m.value;
        if constexpr (std::is_same_v<T, UniformDelay>) return m.min;
        if constexpr (std::is_same_v<T, ExponentialDelay>) return m.base;
        if constexpr (std::is_same_v<T, LogNormalDelay>) return m.base;
      },
      d);
}

bool ChannelConfig::is_ideal() const {
  const auto* c = std::get_if<ConstantDelay>(&delay);
  return !range && !line_of_sight && std::holds_alternative<NoLoss>(loss) && c != nullptr &&
         c->value == 0.0;
}

Channel::Link& Channel::link(std::uint32_t sender, std::uint32_t receiver) {
  const std::uint64_t key = (static_cast<std::uint64_t>(sender) << 32) | receiver;
  auto it = links_.find(key);
  if (it == links_.end()) {
    it = links_
             .emplace(key, Link{RandomStream(seed_, key, "link-loss"),
                                RandomStream(seed_, key, "link-delay"), false})
             .first;
  }
  return it->second;
}

bool Channel::in_reach(Vec2 from, Vec2 to) const {
  if (config_.range && distance(from, to) > *config_.range) return false;
  if (config_.line_of_sight && !env_.segment_inside(from, to)) return false;
  return true;
}

Channel::Transmission Channel::transmit(std::uint32_t sender, std::uint32_t receiver, Vec2 from,
                                        Vec2 to) {
  if (config_.range && distance(from, to) > *config_.range) return {Outcome::out_of_range, {}};
  if (config_.line_of_sight && !env_.segment_inside(from, to)) return {Outcome::blocked, {}};
  Link& l = link(sender, receiver);
  const bool lost = std::visit(
      [&](const auto& m) -> bool {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, NoLoss>) return false;
        if constexpr (std::is_same_v<T, BernoulliLoss>) return l.loss.bernoulli(m.p);
        if constexpr (std::is_same_v<T, GilbertElliottLoss>) {
          l.bad = l.bad ? !l.loss.bernoulli(m.p_bad_to_good) : l.loss.bernoulli(m.p_good_to_bad);
          return l.loss.bernoulli(l.bad ? m.loss_bad : m.loss_good);
        }
        if constexpr (std::is_same_v<T, DistanceLoss>)
          return l.loss.bernoulli(m.at(distance(from, to)));
      },
      config_.loss);
  if (lost) return {Outcome::lost, {}};
  const double seconds = std::visit(
      [&](const auto& m) -> double {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, ConstantDelay>) return m.value;
        if constexpr (std::is_same_v<T, UniformDelay>) return l.delay.uniform(m.min, m.max);
        if constexpr (std::is_same_v<T, ExponentialDelay>)
          return m.base + l.delay.exponential(m.mean);
        if constexpr (std::is_same_v<T, LogNormalDelay>)
          return m.base + l.delay.lognormal(m.mu, m.sigma);
      },
      config_.delay);
  return {Outcome::delivered, SimTime::from_seconds(seconds)};
}

}  // namespace covsim
