#pragma once
// The wireless channel: for each (sender, receiver, message) whether it arrives and after
// what delay. Every random draw comes from a stream keyed by the directed link and the
// purpose ("loss", "delay"), so changing one link's model or traffic leaves every other
// link's draws untouched. Gilbert-Elliott keeps a good/bad state per directed link.
//
// Loss models (probabilities):
//   none; bernoulli(p); gilbert_elliott(p_good_to_bad, p_bad_to_good, loss_good, loss_bad),
//   the state stepping once per message on the link before the loss draw; distance(p_min,
//   d_max, exponent): p(d) = min(1, p_min + (1 - p_min) (d / d_max)^exponent).
// Delay models (seconds): constant(value); uniform(min, max); exponential(base, mean):
//   base + Exp(mean); lognormal(base, mu, sigma): base + exp(N(mu, sigma²)).
#include <cstdint>
#include <map>
#include <optional>
#include <variant>

#include "core/geometry/environment.hpp"
#include "core/random_stream.hpp"
#include "core/sim_time.hpp"

namespace covsim {

struct NoLoss {};
struct BernoulliLoss {
  double p = 0.0;
};
struct GilbertElliottLoss {
  double p_good_to_bad = 0.0, p_bad_to_good = 1.0, loss_good = 0.0, loss_bad = 1.0;
  // The long-run fraction of messages lost.
  double stationary_loss() const;
};
struct DistanceLoss {
  double p_min = 0.0, d_max = 1.0, exponent = 2.0;
  double at(double d) const;
};
using LossModel = std::variant<NoLoss, BernoulliLoss, GilbertElliottLoss, DistanceLoss>;

struct ConstantDelay {
  double value = 0.0;
};
struct UniformDelay {
  double min = 0.0, max = 0.0;
};
struct ExponentialDelay {
  double base = 0.0, mean = 0.0;
};
struct LogNormalDelay {
  double base = 0.0, mu = 0.0, sigma = 0.0;
};
using DelayModel = std::variant<ConstantDelay, UniformDelay, ExponentialDelay, LogNormalDelay>;
// The least delay a model can give.
double minimum_delay(const DelayModel& d);

struct ChannelConfig {
  std::optional<double> range;  // unlimited when unset
  bool line_of_sight = false;   // walls block: the straight link must lie in Ω
  LossModel loss = NoLoss{};
  DelayModel delay = ConstantDelay{0.0};
  // The default channel (unlimited, lossless, instantaneous) is equivalent to every robot
  // knowing every other robot's state at once.
  bool is_ideal() const;
};

class Channel {
 public:
  Channel(ChannelConfig config, std::uint64_t seed, const Environment& env)
      : config_(std::move(config)), seed_(seed), env_(env) {}
  const ChannelConfig& config() const { return config_; }

  enum class Outcome { delivered, out_of_range, blocked, lost };
  struct Transmission {
    Outcome outcome;
    SimTime delay;  // when delivered
  };
  // One message on the directed link sender -> receiver, at the given positions.
  Transmission transmit(std::uint32_t sender, std::uint32_t receiver, Vec2 from, Vec2 to);
  // Whether the link is up at all (range and line of sight), as for the communication graph.
  bool in_reach(Vec2 from, Vec2 to) const;

 private:
  struct Link {
    RandomStream loss, delay;
    bool bad = false;
  };
  Link& link(std::uint32_t sender, std::uint32_t receiver);

  ChannelConfig config_;
  std::uint64_t seed_;
  const Environment& env_;
  std::map<std::uint64_t, Link> links_;
};

}  // namespace covsim
