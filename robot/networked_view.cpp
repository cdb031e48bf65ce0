#include "robot/networked_view.hpp"

#include <algorithm>
#include <stdexcept>

#include "robot/event_classes.hpp"

namespace covsim {

NetworkedView::NetworkedView(Kernel& kernel, const Environment& env, const NetworkConfig& config,
                             const GeneratorState& state, MapExchange* maps)
    : kernel_(kernel),
      config_(config),
      state_(state),
      maps_(maps),
      channel_(std::make_unique<Channel>(config.channel, kernel.seed(), env)) {
  const std::vector<Vec2>& positions = state.points(Generators::positions);
  const std::size_t n = positions.size();
  if (config.channel.range) receivers_.emplace(*config.channel.range, positions);
  tables_.resize(n);
  inboxes_.resize(n);
  cell_caches_.resize(2 * n);
  next_seq_.assign(n, 0);
  acquired_.assign(n, false);
  if (config.channel.model) {
    session_ = config.channel.model->open(ChannelContext{env, kernel.seed(), positions});
    sent_.resize(n);
    kernel_.attach_peer(this);
  }
  broadcast_kind_ = kernel_.add_kind(
      "broadcast", [this](Kernel& k, const Event& ev) { broadcast(k, ev.entity); });
  deliver_kind_ = kernel_.add_kind("deliver", [this](Kernel&, const Event& ev) {
    if (ev.payload == kInbox) {
      // Every message sent to this robot with no delay since its inbox was last read, in
      // the order sent: as their own events would have run (see transmit()).
      std::vector<std::uint32_t>& inbox = inboxes_[ev.entity];
      for (std::uint32_t slot : inbox)
        receive(ev.entity, slot);
      inbox.clear();
    } else if (session_) {
      receive_radio(ev.entity, static_cast<std::uint32_t>(ev.payload));
    } else {
      receive(ev.entity, static_cast<std::uint32_t>(ev.payload));
    }
  });
}

NetworkedView::~NetworkedView() {
  if (session_) kernel_.attach_peer(nullptr);
}

NetworkTotals NetworkedView::totals(bool radio) const {
  NetworkTotals t = totals_;
  t.latency_mean = latency_.mean();
  t.latency_p95 = latency_.quantile(0.95);
  if (session_) {
    // Not received is lost: the radio does not say which receiver was out of reach.
    t.lost = t.sent - t.delivered;
    if (radio) t.radio = session_->totals();
  }
  return t;
}

void NetworkedView::motion_clock(SimTime first, SimTime period) {
  motion_first_ = first;
  motion_period_ = period;
}

SimTime NetworkedView::advance_to(Kernel& k, SimTime t, SimTime limit) {
  // The next motion step at or after t: the radio gets nothing new before it.
  SimTime until = t;
  if (motion_period_ > SimTime::zero() && t > motion_first_) {
    const std::int64_t p = motion_period_.ns();
    const std::int64_t steps = (t.ns() - motion_first_.ns() + p - 1) / p;
    until = SimTime::from_ns(motion_first_.ns() + steps * p);
  } else if (motion_period_ > SimTime::zero()) {
    until = motion_first_;
  }
  until = std::max(t, std::min(until, limit));
  // Every broadcast up to `until`, by time and then robot (the kernel's order at one time);
  // the kernel dispatches the events at `until` itself before it asks again.
  struct Announced {
    SimTime at;
    std::uint32_t sender;
    std::uint64_t seq;
  };
  std::vector<Announced> sends;
  const std::int64_t period = config_.broadcast_period.ns();
  for (std::uint32_t i = 0; i < phases_.size(); ++i) {
    for (;;) {
      const SimTime at =
          phases_[i] + SimTime::from_ns(static_cast<std::int64_t>(announced_[i]) * period);
      if (at > until) break;
      sends.push_back({at, i, announced_[i]++});
    }
  }
  std::sort(sends.begin(), sends.end(), [](const Announced& a, const Announced& b) {
    return a.at != b.at ? a.at < b.at : a.sender < b.sender;
  });
  // Announced ahead of their content: a robot that maps Ω reserves the most map bytes a
  // broadcast carries in each.
  const auto bytes = static_cast<std::uint32_t>(kStateMessageBytes +
                                                (maps_ != nullptr ? maps_->payload_limit() : 0));
  for (const Announced& s : sends)
    session_->broadcast(s.sender, s.seq, bytes, s.at);
  announced_to_ = until;
  receptions_.clear();
  session_->advance(until, receptions_);
  for (const Reception& r : receptions_) {
    if (r.sender >= sent_.size() || r.receiver >= sent_.size() || r.receiver == r.sender ||
        r.seq >= announced_[r.sender])
      throw std::runtime_error("the simulated radio reported a message nobody sent");
    std::uint32_t index;
    if (!free_pending_.empty()) {
      index = free_pending_.back();
      free_pending_.pop_back();
      pending_[index] = r;
    } else {
      index = static_cast<std::uint32_t>(pending_.size());
      pending_.push_back(r);
    }
    k.schedule_at(r.at, deliver_kind_, r.receiver, event_class::deliver, index);
  }
  return until;
}

void NetworkedView::receive_radio(std::uint32_t j, std::uint32_t index) {
  const Reception r = pending_[index];
  free_pending_.push_back(index);
  // Sent before now (a frame takes time on the air), so its broadcast has run.
  const std::deque<StateMessage>& history = sent_[r.sender];
  if (history.empty() || r.seq < history.front().seq || r.seq > history.back().seq)
    throw std::runtime_error("the simulated radio delivered a message covsim no longer holds");
  const StateMessage& m = history[r.seq - history.front().seq];
  ++totals_.delivered;
  latency_.add((kernel_.now() - m.sent).seconds());
  if (maps_ != nullptr) maps_->merge(j, m.map);
  tables_[j].update(m);
}

void NetworkedView::start(SimTime t0) {
  t0_ = t0;
  const Period period = Period::from_ns(config_.broadcast_period.ns());
  for (std::uint32_t i = 0; i < tables_.size(); ++i) {
    SimTime phase = t0;
    if (config_.phases_random()) {
      phase += SimTime::from_seconds(
          kernel_.stream(i, "broadcast-phase").uniform(0.0, period.seconds()));
    }
    kernel_.schedule_periodic(period, phase, broadcast_kind_, i, event_class::broadcast);
    phases_.push_back(phase);
  }
  announced_.assign(tables_.size(), 0);
}

bool NetworkedView::ready(std::uint32_t i) {
  if (acquired_[i]) return true;
  const SimTime now = kernel_.now();
  if (now < t0_ + config_.acquire_time()) return false;
  // Nobody heard yet: wait for a first message, up to the deadline.
  if (tables_[i].size() == 0 && now < t0_ + config_.acquire_deadline()) return false;
  acquired_[i] = true;
  return true;
}

void NetworkedView::moved(std::uint32_t i) {
  if (receivers_) receivers_->moved(i, state_.points(Generators::positions)[i]);
  if (session_) session_->moved(i, state_.points(Generators::positions)[i]);
}

void NetworkedView::refresh(std::uint32_t i) {
  if (config_.staleness) tables_[i].drop_stale(kernel_.now(), *config_.staleness);
}

Knowledge NetworkedView::knowledge(std::uint32_t i, Generators kind) const {
  const bool positions = kind == Generators::positions;
  const Vec2 own = state_.points(kind)[i];
  known_.clear();
  std::size_t self = 0;
  bool placed = false;
  for (const StateMessage& m : tables_[i].entries()) {  // by sender id
    if (!placed && m.sender > i) {
      self = known_.size();
      known_.push_back(own);
      placed = true;
    }
    known_.push_back(positions ? m.position : m.virtual_generator);
  }
  if (!placed) {
    self = known_.size();
    known_.push_back(own);
  }
  return Knowledge{known_,  self,         kind,
                   nullptr, std::nullopt, &cell_caches_[2 * i + (positions ? 1 : 0)]};
}

void NetworkedView::broadcast(Kernel& k, std::uint32_t i) {
  const std::vector<Vec2>& positions = state_.points(Generators::positions);
  StateMessage m{
      i, next_seq_[i]++, k.now(), state_.points(Generators::virtual_generators)[i], positions[i],
      {}};
  if (maps_ != nullptr) m.map = maps_->pack(i);
  const auto n = static_cast<std::uint32_t>(tables_.size());
  totals_.sent += n - 1;
  if (session_) {
    // Announced to the radio ahead (advance_to): only its content is new.
    if (m.seq >= announced_[i] || k.now() > announced_to_)
      throw std::logic_error("a broadcast the simulated radio was not told of");
    std::deque<StateMessage>& history = sent_[i];
    history.push_back(m);
    if (history.size() > kKeptMessages) history.pop_front();
    return;
  }
  const std::uint32_t slot = new_slot(m);
  // With a finite range only the robots near the sender can hear it; the others are out of
  // range, and their links draw nothing, as if tested one by one.
  if (receivers_) {
    receivers_->candidates(positions[i], candidates_);
    const auto others = static_cast<std::uint64_t>(
        candidates_.size() - std::count(candidates_.begin(), candidates_.end(), i));
    totals_.unreachable += (n - 1) - others;
    for (std::uint32_t j : candidates_) {
      if (j != i) transmit(k, slot, i, j);
    }
  } else {
    for (std::uint32_t j = 0; j < n; ++j) {
      if (j != i) transmit(k, slot, i, j);
    }
  }
  if (in_flight_[slot].deliveries == 0) free_slots_.push_back(slot);  // nothing delivered
}

std::uint32_t NetworkedView::new_slot(const StateMessage& m) {
  std::uint32_t slot;
  if (!free_slots_.empty()) {
    slot = free_slots_.back();
    free_slots_.pop_back();
  } else {
    slot = static_cast<std::uint32_t>(in_flight_.size());
    in_flight_.emplace_back();
  }
  in_flight_[slot] = {m, 0};
  return slot;
}

void NetworkedView::transmit(Kernel& k, std::uint32_t slot, std::uint32_t i, std::uint32_t j) {
  const std::vector<Vec2>& positions = state_.points(Generators::positions);
  const Channel::Transmission t = channel_->transmit(i, j, positions[i], positions[j]);
  if (t.outcome == Channel::Outcome::lost) ++totals_.lost;
  if (t.outcome == Channel::Outcome::out_of_range || t.outcome == Channel::Outcome::blocked)
    ++totals_.unreachable;
  if (t.outcome != Channel::Outcome::delivered) return;
  ++totals_.delivered;
  ++in_flight_[slot].deliveries;
  if (t.delay > SimTime::zero()) {
    k.schedule_in(t.delay, deliver_kind_, j, event_class::deliver, slot);
    return;
  }
  // Messages without delay wait in the receiver's inbox, read by one event scheduled with the
  // first. Its key (now, deliver, j) precedes theirs, and every other event with that time,
  // class and entity was scheduled before now (a delayed message), so the table sees the
  // same updates in the same order as with an event per message, in a 60th of the events.
  std::vector<std::uint32_t>& inbox = inboxes_[j];
  if (inbox.empty()) k.schedule_in(SimTime::zero(), deliver_kind_, j, event_class::deliver, kInbox);
  inbox.push_back(slot);
}

void NetworkedView::receive(std::uint32_t j, std::uint32_t slot) {
  const StateMessage& m = in_flight_[slot].message;
  latency_.add((kernel_.now() - m.sent).seconds());
  if (maps_ != nullptr) maps_->merge(j, m.map);
  tables_[j].update(m);
  if (--in_flight_[slot].deliveries == 0) free_slots_.push_back(slot);
}

}  // namespace covsim
