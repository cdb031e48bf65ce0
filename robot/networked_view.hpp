#pragma once
// Decentralized operation: every robot broadcasts its state (virtual generator, position, a
// sequence number, the send time) every broadcast period through the channel (range, line
// of sight, loss and delay models); delivered messages update the receiver's neighbour
// table (the newest by sequence number), and a robot knows what its table holds. Events:
// "broadcast" (class 3) per robot; "deliver" (class 4) per delayed message, and one per
// receiver and instant for the messages without delay.
//
// Algorithm 1 acquires the neighbours (line 3) before its first Lloyd step: a robot is
// ready once NetworkConfig::acquire_time() has passed since the start and it has heard
// somebody, or once acquire_deadline() has passed (it then goes alone, its cell Ω).
//
// With a simulated radio (network.channel, e.g. ns3_wifi) the channel is a session run
// beside the kernel (KernelPeer), which runs it ahead from one motion step to the next:
// broadcasts are periodic, so each robot's broadcasts up to the next step are announced to it
// with their times, numbers and sizes (their content is never needed by the radio), and the
// step's moves follow at the step's time. Each reception it reports becomes a "deliver"
// event at its time, which reads the message then. A message is kept until its sender has
// sent kKeptMessages newer ones.
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "core/kernel.hpp"
#include "net/channel.hpp"
#include "net/latency_stats.hpp"
#include "net/neighbor_table.hpp"
#include "net/receiver_grid.hpp"
#include "robot/coverage_config.hpp"
#include "robot/generator_state.hpp"
#include "robot/map_exchange.hpp"
#include "robot/neighbor_view.hpp"

namespace covsim {

class NetworkedView final : public NeighborView, private KernelPeer {
 public:
  // maps: robots that map Ω, whose broadcasts carry map readings (null: none).
  NetworkedView(Kernel& kernel, const Environment& env, const NetworkConfig& config,
                const GeneratorState& state, MapExchange* maps = nullptr);
  ~NetworkedView() override;
  NetworkedView(const NetworkedView&) = delete;
  NetworkedView& operator=(const NetworkedView&) = delete;
  bool decentralized() const override { return true; }
  void start(SimTime t0) override;
  bool ready(std::uint32_t i) override;
  void refresh(std::uint32_t i) override;
  void moved(std::uint32_t i) override;
  void motion_clock(SimTime first, SimTime period) override;
  Knowledge knowledge(std::uint32_t i, Generators kind) const override;
  NetworkTotals totals(bool radio = false) const override;

  const Channel& channel() const { return *channel_; }
  const NetworkConfig& config() const { return config_; }
  const std::vector<NeighborTable>& tables() const { return tables_; }

 private:
  void broadcast(Kernel& k, std::uint32_t i);
  // The broadcast's message on the link i -> j: the channel's verdict, counted, and its
  // delivery, which shares the broadcast's slot.
  void transmit(Kernel& k, std::uint32_t slot, std::uint32_t i, std::uint32_t j);
  std::uint32_t new_slot(const StateMessage& m);
  // Robot j reads the message in `slot`.
  void receive(std::uint32_t j, std::uint32_t slot);
  // Runs the simulated radio to the next motion step at or after t (not past `limit`),
  // announcing the broadcasts before it; its receptions become delivery events.
  SimTime advance_to(Kernel& k, SimTime t, SimTime limit) override;
  // Robot j hears the radio's reception `index` (of pending_).
  void receive_radio(std::uint32_t j, std::uint32_t index);

  // A sender's messages a simulated radio may still deliver: far more than its MAC queue
  // holds (ns-3's: 500 frames).
  static constexpr std::size_t kKeptMessages = 1024;

  Kernel& kernel_;
  NetworkConfig config_;
  const GeneratorState& state_;
  MapExchange* maps_;
  std::unique_ptr<Channel> channel_;
  std::unique_ptr<ChannelSession> session_;     // a simulated radio; null: channel_ decides
  std::vector<std::deque<StateMessage>> sent_;  // per sender, with a session
  std::vector<Reception> receptions_;
  std::vector<Reception> pending_;  // receptions scheduled, not yet read
  std::vector<std::uint32_t> free_pending_;
  std::vector<SimTime> phases_;           // each robot's first broadcast
  std::vector<std::uint64_t> announced_;  // broadcasts announced to the radio, per robot
  SimTime announced_to_;                  // every broadcast up to it is announced
  SimTime motion_first_, motion_period_;  // the loop-2 steps' clock; period 0: unknown
  LatencyStats latency_;
  std::optional<ReceiverGrid> receivers_;  // with a finite range only
  std::vector<std::uint32_t> candidates_;
  EventKind broadcast_kind_ = 0, deliver_kind_ = 0;
  std::vector<NeighborTable> tables_;
  std::vector<std::uint64_t> next_seq_;
  // Messages on their way, one slot per broadcast however many deliveries it has pending
  // (tens with a ranged network), freed by the last.
  struct InFlight {
    StateMessage message;
    std::uint32_t deliveries = 0;
  };
  std::vector<InFlight> in_flight_;
  std::vector<std::uint32_t> free_slots_;
  // Per robot, the slots of messages sent to it without delay and not yet read, and the
  // payload of the one delivery event that reads them.
  std::vector<std::vector<std::uint32_t>> inboxes_;
  static constexpr std::uint64_t kInbox = UINT64_MAX;
  std::vector<bool> acquired_;
  SimTime t0_;
  NetworkTotals totals_;
  mutable std::vector<Vec2> known_;  // what knowledge() returns points into
  // Each robot's own cell of its virtual generator (2 i) and of its position (2 i + 1).
  mutable std::vector<OwnCellCache> cell_caches_;
};

}  // namespace covsim
