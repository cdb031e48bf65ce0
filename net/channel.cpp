#include "net/channel.hpp"

#include <algorithm>

#include "net/constant_delay.hpp"
#include "net/no_loss.hpp"

namespace covsim {

bool ChannelConfig::is_ideal() const {
  return !model && !range && !line_of_sight && (!loss || loss->lossless()) &&
         (!delay || delay->instantaneous());
}

ChannelEntry abstract_channel_entry() {
  ChannelEntry e;
  e.name = "abstract";
  e.description =
      "covsim's own: network.range, line_of_sight, loss and delay decide each link's message";
  e.make = [](const Params&) { return std::shared_ptr<const ChannelModel>(); };
  return e;
}

Channel::Channel(ChannelConfig config, std::uint64_t seed, const Environment& env)
    : config_(std::move(config)), seed_(seed), env_(env) {
  if (!config_.loss) config_.loss = std::make_shared<const NoLoss>();
  if (!config_.delay) config_.delay = std::make_shared<const ConstantDelay>(0.0);
}

Channel::Link& Channel::link(std::uint32_t sender, std::uint32_t receiver) {
  if (sender >= outgoing_.size()) outgoing_.resize(sender + 1);
  Outgoing& out = outgoing_[sender];
  const auto it = std::lower_bound(out.receivers.begin(), out.receivers.end(), receiver);
  const auto at = it - out.receivers.begin();
  if (it == out.receivers.end() || *it != receiver) {
    // The streams are keyed by the directed link, whatever the order links are first used.
    const std::uint64_t key = (static_cast<std::uint64_t>(sender) << 32) | receiver;
    out.receivers.insert(it, receiver);
    out.links.insert(out.links.begin() + at,
                     Link{RandomStream(seed_, key, "link-loss"),
                          RandomStream(seed_, key, "link-delay"), LinkState{}});
  }
  return out.links[static_cast<std::size_t>(at)];
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
  if (config_.loss->lost(l.state, l.loss, distance(from, to))) return {Outcome::lost, {}};
  return {Outcome::delivered, SimTime::from_seconds(config_.delay->sample(l.delay))};
}

}  // namespace covsim
