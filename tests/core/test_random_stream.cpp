#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "core/kernel.hpp"
#include "core/random_stream.hpp"

using namespace covsim;

namespace {
std::vector<std::uint64_t> draws(RandomStream s, int n) {
  std::vector<std::uint64_t> v;
  for (int i = 0; i < n; ++i)
    v.push_back(s.next_u64());
  return v;
}

// A toy model: n entities, each drawing `extra[i]` numbers before recording 100 draws.
std::vector<std::vector<double>> model(std::uint64_t seed, int n, const std::vector<int>& extra) {
  Kernel k(seed);
  std::vector<RandomStream> streams;
  for (int i = 0; i < n; ++i)
    streams.push_back(k.stream(static_cast<std::uint64_t>(i), "motion"));
  std::vector<std::vector<double>> out(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    auto& s = streams[static_cast<std::size_t>(i)];
    for (int j = 0; j < extra[static_cast<std::size_t>(i)]; ++j)
      s.uniform01();
    for (int j = 0; j < 100; ++j)
      out[static_cast<std::size_t>(i)].push_back(s.uniform01());
  }
  return out;
}
}  // namespace

TEST_CASE("a stream is fixed by (seed, entity, purpose) alone", "[random]") {
  CHECK(draws(RandomStream(1, 2, "loss"), 100) == draws(RandomStream(1, 2, "loss"), 100));
  CHECK(draws(RandomStream(1, 2, "loss"), 10) != draws(RandomStream(2, 2, "loss"), 10));
  CHECK(draws(RandomStream(1, 2, "loss"), 10) != draws(RandomStream(1, 3, "loss"), 10));
  CHECK(draws(RandomStream(1, 2, "loss"), 10) != draws(RandomStream(1, 2, "delay"), 10));
  // Swapping entity and seed must not give the same stream.
  CHECK(draws(RandomStream(2, 1, "loss"), 10) != draws(RandomStream(1, 2, "loss"), 10));
}

TEST_CASE("adding an entity or drawing more in one stream leaves the others unchanged",
          "[random]") {
  const auto base = model(42, 3, {0, 0, 0});
  const auto more_entities = model(42, 5, {0, 0, 0, 7, 3});
  const auto more_draws = model(42, 3, {0, 11, 0});
  for (std::size_t i = 0; i < 3; ++i)
    CHECK(base[i] == more_entities[i]);
  CHECK(base[0] == more_draws[0]);
  CHECK(base[2] == more_draws[2]);
  CHECK(base[1] != more_draws[1]);
}

TEST_CASE("the generator is xoshiro256++ as published", "[random]") {
  // Reference outputs of xoshiro256++ from the state {1, 2, 3, 4}, computed independently.
  const auto v = draws(RandomStream::from_state({1, 2, 3, 4}), 5);
  CHECK(v == std::vector<std::uint64_t>{41943041ULL, 58720359ULL, 3588806011781223ULL,
                                        3591011842654386ULL, 9228616714210784205ULL});
}

TEST_CASE("distributions have the right moments", "[random]") {
  RandomStream s(3, 0, "moments");
  const int n = 200000;
  double sum_u = 0, sum_e = 0, sum_n = 0, sum_n2 = 0;
  int bern = 0;
  std::vector<int> bins(7, 0);
  for (int i = 0; i < n; ++i) {
    const double u = s.uniform01();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    sum_u += u;
    sum_e += s.exponential(2.0);
    const double z = s.normal();
    sum_n += z;
    sum_n2 += z * z;
    bern += s.bernoulli(0.3) ? 1 : 0;
    ++bins[s.below(7)];
  }
  // Tolerances are five standard errors of each estimate.
  CHECK(std::abs(sum_u / n - 0.5) < 5 * std::sqrt(1.0 / 12 / n));
  CHECK(std::abs(sum_e / n - 2.0) < 5 * 2.0 / std::sqrt(n));
  CHECK(std::abs(sum_n / n) < 5 / std::sqrt(n));
  CHECK(std::abs(sum_n2 / n - 1.0) < 5 * std::sqrt(2.0 / n));
  CHECK(std::abs(bern / double(n) - 0.3) < 5 * std::sqrt(0.21 / n));
  double chi2 = 0;
  for (int b : bins)
    chi2 += (b - n / 7.0) * (b - n / 7.0) / (n / 7.0);
  CHECK(chi2 < 22.5);  // chi-square, 6 degrees of freedom, p = 0.001
}
