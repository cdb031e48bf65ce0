#pragma once
// The wireless channel's model, an extension point: this interface plus one entry in
// channel_registry() (the scenario's network.channel.type). "abstract" is covsim's own
// channel (net/channel.hpp): range, line of sight and the loss and delay models, decided per
// link when a message is sent; its factory makes no model object, as the networked view
// runs it inline. A model that simulates the radio (ns3_wifi) is opened once per run as a
// session that runs beside the kernel (KernelPeer): broadcasts and moves go in, receptions
// come out with their times.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/registry.hpp"
#include "core/sim_time.hpp"
#include "core/vec2.hpp"
#include "geometry/environment.hpp"

namespace covsim {

struct ChannelContext {
  const Environment& env;
  std::uint64_t seed;           // the run's
  std::vector<Vec2> positions;  // the robots' at the start
};

struct Reception {
  SimTime at;
  std::uint32_t receiver = 0, sender = 0;
  std::uint64_t seq = 0;  // the sender's message sequence number
};

// What a simulated radio counted, for the run's measures.
struct RadioTotals {
  std::uint64_t transmissions = 0;  // frames put on the air
  std::uint64_t phy_drops = 0;      // receptions that began and failed (collisions, noise)
  std::uint64_t mac_drops = 0;      // frames dropped before they reached the air
  double occupancy = 0;             // mean over robots of the time their radio found the air busy
};

class ChannelSession {
 public:
  virtual ~ChannelSession() = default;
  // Robot `sender` will broadcast its message `seq`, `bytes` long, at time `at` (not before
  // the last advance's time): announced ahead, as a broadcast's time, number and size are
  // known before its content. Announcements of one time come in the order they are sent.
  virtual void broadcast(std::uint32_t sender, std::uint64_t seq, std::uint32_t bytes,
                         SimTime at) = 0;
  // Robot `robot` is at `position` from the last advance's time on.
  virtual void moved(std::uint32_t robot, Vec2 position) = 0;
  // Applies the moves, then the broadcasts, and runs the channel to t; appends the receptions
  // from the last advance's time to t, in the order they happened.
  virtual void advance(SimTime t, std::vector<Reception>& out) = 0;
  virtual RadioTotals totals() = 0;
};

class ChannelModel {
 public:
  virtual ~ChannelModel() = default;
  virtual std::unique_ptr<ChannelSession> open(const ChannelContext& context) const = 0;
  // Which of the network section's own keys the model replaces: a scenario that sets one of
  // them with this model is refused (ns3_wifi decides range, loss and delay itself).
  virtual std::vector<std::string> replaces() const = 0;
};

// The factory returns null for "abstract" (the inline channel).
using ChannelEntry = Component<std::function<std::shared_ptr<const ChannelModel>(const Params&)>>;

}  // namespace covsim
