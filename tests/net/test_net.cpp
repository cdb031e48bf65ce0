#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "net/bernoulli_loss.hpp"
#include "net/channel.hpp"
#include "net/comm_graph.hpp"
#include "net/constant_delay.hpp"
#include "net/distance_loss.hpp"
#include "net/exponential_delay.hpp"
#include "net/gilbert_elliott_loss.hpp"
#include "net/lognormal_delay.hpp"
#include "net/neighbor_table.hpp"
#include "net/no_loss.hpp"
#include "net/peer_process.hpp"
#include "net/receiver_grid.hpp"
#include "net/uniform_delay.hpp"

using namespace covsim;

namespace {
template <class T, class... A>
std::shared_ptr<const T> make(A... a) {
  return std::make_shared<const T>(a...);
}

const Environment& room() {
  static const Environment env({{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                               {{{4, 2}, {6, 2}, {6, 8}, {4, 8}}});
  return env;
}

double loss_rate(Channel& c, int n, Vec2 a = {1, 1}, Vec2 b = {2, 1}) {
  int lost = 0;
  for (int i = 0; i < n; ++i)
    lost += c.transmit(0, 1, a, b).outcome == Channel::Outcome::lost;
  return static_cast<double>(lost) / n;
}
}  // namespace

TEST_CASE("Bernoulli loss matches p over many messages", "[net]") {
  for (double p : {0.0, 0.1, 0.3, 0.9}) {
    Channel c(ChannelConfig{std::nullopt, false, make<BernoulliLoss>(p), nullptr, nullptr}, 7,
              room());
    const int n = 100000;
    CHECK(std::abs(loss_rate(c, n) - p) <= 5 * std::sqrt(p * (1 - p) / n) + 1e-12);
  }
}

TEST_CASE("Gilbert-Elliott loss matches its stationary value", "[net]") {
  const auto ge = make<GilbertElliottLoss>(0.05, 0.2, 0.01, 0.6);
  CHECK(ge->stationary_loss() == Approx(0.8 * 0.01 + 0.2 * 0.6));
  Channel c(ChannelConfig{std::nullopt, false, ge, nullptr, nullptr}, 3, room());
  // Losses come in bursts, so the bound is wider than for independent draws: the chain
  // mixes in about 1 / (0.05 + 0.2) = 4 steps.
  const int n = 400000;
  CHECK(std::abs(loss_rate(c, n) - ge->stationary_loss()) <= 5 * std::sqrt(0.25 * 10.0 / n));
}

TEST_CASE("distance loss follows its formula", "[net]") {
  const auto d = make<DistanceLoss>(0.1, 5.0, 2.0);
  CHECK(d->at(0.0) == Approx(0.1));
  CHECK(d->at(2.5) == Approx(0.1 + 0.9 * 0.25));
  CHECK(d->at(7.0) == 1.0);
  Channel c(ChannelConfig{std::nullopt, false, d, nullptr, nullptr}, 5, room());
  const int n = 50000;
  const double p = d->at(3.0);
  CHECK(std::abs(loss_rate(c, n, {0.5, 9}, {3.5, 9}) - p) <= 5 * std::sqrt(p * (1 - p) / n));
}

TEST_CASE("no message arrives before its minimum delay", "[net]") {
  const std::shared_ptr<const DelayModel> models[] = {
      make<ConstantDelay>(0.02), make<UniformDelay>(0.01, 0.05), make<ExponentialDelay>(0.03, 0.1),
      make<LogNormalDelay>(0.005, -4.0, 0.5)};
  for (const auto& m : models) {
    Channel c(ChannelConfig{std::nullopt, false, nullptr, m, nullptr}, 9, room());
    double least = INFINITY;
    for (int i = 0; i < 20000; ++i) {
      const auto t = c.transmit(2, 3, {1, 1}, {2, 2});
      REQUIRE(t.outcome == Channel::Outcome::delivered);
      least = std::min(least, t.delay.seconds());
    }
    CHECK(least >= m->minimum() - 1e-9);
  }
  // Means, where they are simple: uniform (0.03) and exponential (0.03 + 0.1).
  Channel u(ChannelConfig{std::nullopt, false, nullptr, make<UniformDelay>(0.01, 0.05), nullptr}, 1,
            room());
  double sum = 0;
  for (int i = 0; i < 20000; ++i)
    sum += u.transmit(0, 1, {1, 1}, {2, 2}).delay.seconds();
  CHECK(sum / 20000 == Approx(0.03).epsilon(0.01));
}

TEST_CASE("each link draws from its own streams", "[net]") {
  auto outcomes = [](bool extra_traffic) {
    Channel c(ChannelConfig{std::nullopt, false, make<BernoulliLoss>(0.5),
                            make<UniformDelay>(0.0, 1.0), nullptr},
              11, room());
    std::vector<double> seen;
    for (int i = 0; i < 200; ++i) {
      if (extra_traffic) c.transmit(0, 1, {1, 1}, {2, 1});  // more messages on another link
      const auto t = c.transmit(2, 1, {1, 1}, {2, 1});
      seen.push_back(t.outcome == Channel::Outcome::lost ? -1.0 : t.delay.seconds());
    }
    return seen;
  };
  CHECK(outcomes(false) == outcomes(true));
}

TEST_CASE("range and line of sight", "[net]") {
  Channel c(ChannelConfig{3.0, true, nullptr, nullptr, nullptr}, 1, room());
  CHECK(c.transmit(0, 1, {1, 1}, {3, 1}).outcome == Channel::Outcome::delivered);
  CHECK(c.transmit(0, 1, {1, 1}, {5, 1}).outcome == Channel::Outcome::out_of_range);
  CHECK(c.transmit(0, 1, {3.5, 5}, {6.5, 5}).outcome ==
        Channel::Outcome::blocked);  // through the wall
  CHECK(c.in_reach({3.5, 1}, {6.5, 1}));
  CHECK_FALSE(c.in_reach({3.5, 5}, {6.5, 5}));
  CHECK(ChannelConfig{}.is_ideal());
  CHECK((ChannelConfig{std::nullopt, false, make<NoLoss>(), make<ConstantDelay>(0.0), nullptr}
             .is_ideal()));
  CHECK_FALSE(
      (ChannelConfig{std::nullopt, false, nullptr, make<ConstantDelay>(0.01), nullptr}.is_ideal()));
  CHECK_FALSE(
      (ChannelConfig{std::nullopt, false, make<BernoulliLoss>(0.0), nullptr, nullptr}.is_ideal()));
}

TEST_CASE("neighbour tables keep the newest and drop the stale", "[net]") {
  NeighborTable t;
  auto msg = [](std::uint32_t from, std::uint64_t seq, double sent) {
    return StateMessage{from,   seq, SimTime::from_seconds(sent), {static_cast<double>(seq), 0},
                        {0, 0}, {}};
  };
  CHECK(t.update(msg(1, 5, 1.0)));
  CHECK_FALSE(t.update(msg(1, 3, 0.5)));  // older, arriving late
  REQUIRE(t.find(1) != nullptr);
  CHECK(t.find(1)->seq == 5);
  CHECK(t.update(msg(1, 6, 1.1)));
  CHECK(t.update(msg(2, 1, 0.2)));
  CHECK(t.update(msg(0, 1, 0.9)));  // a lower sender id, heard later, still comes first
  CHECK(t.entries().front().sender == 0);
  const std::vector<double> ages = t.ages(SimTime::from_seconds(1.5));
  REQUIRE(ages.size() == 3);
  CHECK(ages[0] == Approx(0.6));  // sender 0, sent at 0.9
  CHECK(ages[1] == Approx(0.4));  // sender 1, sent at 1.1
  CHECK(ages[2] == Approx(1.3));  // sender 2, sent at 0.2
  t.drop_stale(SimTime::from_seconds(1.5), SimTime::from_seconds(1.0));
  CHECK(t.size() == 2);
  CHECK(t.find(0) != nullptr);
  CHECK(t.find(1) != nullptr);
  CHECK(t.find(2) == nullptr);
}

TEST_CASE("communication graph measures on known graphs", "[net]") {
  // A path of 4 nodes: λ2 = 2 - √2.
  const CommGraphMetrics path = comm_graph_metrics(4, {{0, 1}, {1, 2}, {2, 3}});
  CHECK(path.components == 1);
  CHECK(path.largest_component == 4);
  CHECK(path.diameter == 3);
  CHECK(path.average_degree == Approx(1.5));
  CHECK(path.algebraic_connectivity == Approx(2 - std::sqrt(2.0)));
  // The complete graph K4: λ2 = 4.
  const CommGraphMetrics k4 =
      comm_graph_metrics(4, {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}});
  CHECK(k4.diameter == 1);
  CHECK(k4.algebraic_connectivity == Approx(4.0));
  // Two separate edges and an isolated node.
  const CommGraphMetrics split = comm_graph_metrics(5, {{0, 1}, {2, 3}});
  CHECK(split.components == 3);
  CHECK(split.largest_component == 2);
  CHECK(split.diameter == 1);
  CHECK(split.algebraic_connectivity == 0.0);
}

TEST_CASE("the complete graph's measures in closed form equal the general ones", "[net]") {
  for (std::size_t n = 0; n <= 40; ++n) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = a + 1; b < n; ++b)
        edges.emplace_back(a, b);
    const CommGraphMetrics general = comm_graph_metrics(n, edges);
    const CommGraphMetrics closed = complete_graph_metrics(n);
    INFO("n = " << n);
    CHECK(closed.components == general.components);
    CHECK(closed.largest_component == general.largest_component);
    CHECK(closed.diameter == general.diameter);
    CHECK(closed.average_degree == Approx(general.average_degree));
    CHECK(closed.algebraic_connectivity == Approx(general.algebraic_connectivity).epsilon(1e-12));
  }
}

TEST_CASE("the receiver grid finds every robot within range as robots move", "[net]") {
  RandomStream rng(11, 0, "receiver-grid");
  const double range = 1.5;
  std::vector<Vec2> positions(400);
  for (Vec2& p : positions)
    p = Vec2{rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0)};
  ReceiverGrid grid(range, positions);
  std::vector<std::uint32_t> found;
  for (int step = 0; step < 20000; ++step) {
    const auto i = static_cast<std::uint32_t>(rng.below(positions.size()));
    // Mostly motion steps, now and then a jump across the room.
    const double reach = rng.below(20) == 0 ? 10.0 : 0.1;
    positions[i] += Vec2{rng.uniform(-reach, reach), rng.uniform(-reach, reach)};
    grid.moved(i, positions[i]);
    const Vec2 p = rng.below(2) == 0 ? positions[rng.below(positions.size())]
                                     : Vec2{rng.uniform(-12.0, 12.0), rng.uniform(-12.0, 12.0)};
    grid.candidates(p, found);
    REQUIRE(std::is_sorted(found.begin(), found.end()));
    REQUIRE(std::adjacent_find(found.begin(), found.end()) == found.end());
    for (std::uint32_t j = 0; j < positions.size(); ++j) {
      if (distance(positions[j], p) <= range)
        REQUIRE(std::binary_search(found.begin(), found.end(), j));
    }
    // A superset, but not the whole swarm: the grid is what makes a broadcast cheap.
    REQUIRE(found.size() < positions.size() / 4);
  }
}

TEST_CASE("a peer's answer timeout counts the time waited, not the time stopped", "[net][peer]") {
  // The peer stops this process for 4 s (as Ctrl-Z and fg would), then answers at once: some
  // 0.3 s of waiting (more on a loaded machine), within a 3 s timeout.
  PeerProcess slow("/bin/sh",
                   {"-c",
                    "sleep 0.2; kill -STOP $PPID; sleep 4; kill -CONT $PPID; sleep 0.1; "
                    "printf '\\001\\000\\000\\000\\002\\000\\000\\000ok'; sleep 5"},
                   3.0);
  std::string payload;
  CHECK(slow.receive(payload) == 1u);
  CHECK(payload == "ok");
  // A peer that really says nothing for longer is still an error.
  PeerProcess silent("/bin/sh", {"-c", "sleep 5"}, 0.5);
  CHECK_THROWS_WITH(silent.receive(payload), Catch::Contains("no answer within 0.5 s"));
}
