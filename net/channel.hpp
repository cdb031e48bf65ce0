#pragma once
// The wireless channel: for each (sender, receiver, message) whether it arrives and after
// what delay. Every random draw comes from a stream keyed by the directed link and the
// purpose ("link-loss", "link-delay"), so changing one link's model or traffic leaves every
// other link's draws untouched. The loss and delay models are components
// (loss_registry(), delay_registry()); each directed link keeps its own state for models
// with memory.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/sim_time.hpp"
#include "geometry/environment.hpp"
#include "net/channel_model.hpp"
#include "net/delay_model.hpp"
#include "net/loss_model.hpp"

namespace covsim {

struct ChannelConfig {
  std::optional<double> range;              // unlimited when unset
  bool line_of_sight = false;               // walls block: the straight link must lie in Ω
  std::shared_ptr<const LossModel> loss;    // unset: no loss
  std::shared_ptr<const DelayModel> delay;  // unset: no delay
  // A simulated radio (network.channel) in place of the above; unset: this channel.
  std::shared_ptr<const ChannelModel> model;
  // The default channel (unlimited, lossless, instantaneous) is equivalent to every robot
  // knowing every other robot's state at once.
  bool is_ideal() const;
};

class Channel {
 public:
  Channel(ChannelConfig config, std::uint64_t seed, const Environment& env);
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
    LinkState state;
  };
  Link& link(std::uint32_t sender, std::uint32_t receiver);

  ChannelConfig config_;
  std::uint64_t seed_;
  const Environment& env_;
  // Each sender's links, created on first use, sorted by receiver: a sender reaches a few
  // dozen robots, so a lookup is a short binary search in memory of its own.
  struct Outgoing {
    std::vector<std::uint32_t> receivers;
    std::vector<Link> links;
  };
  std::vector<Outgoing> outgoing_;
};

// The registry's "abstract" entry: this channel, configured by the network section's keys.
ChannelEntry abstract_channel_entry();

}  // namespace covsim
