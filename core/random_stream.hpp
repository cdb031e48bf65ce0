#pragma once
// A random stream keyed by (seed, entity, purpose). Streams are never handed out in
// creation order: the key alone fixes the sequence, so adding a robot or drawing once more
// in one component leaves every other stream untouched. The distributions are implemented
// here (not std::*_distribution, whose output differs between standard libraries).
#include <array>
#include <cstdint>
#include <limits>
#include <string_view>

namespace covsim {

class RandomStream {
 public:
  using result_type = std::uint64_t;

  RandomStream(std::uint64_t seed, std::uint64_t entity, std::string_view purpose);
  RandomStream(std::uint64_t seed, std::uint64_t entity, std::uint64_t purpose_key);
  // A generator in a given raw state (not all zero), e.g. to check against reference vectors.
  static RandomStream from_state(const std::array<std::uint64_t, 4>& state);

  // xoshiro256++ (Blackman and Vigna), seeded from the key by SplitMix64.
  std::uint64_t next_u64();
  std::uint64_t operator()() { return next_u64(); }
  static constexpr std::uint64_t min() { return 0; }
  static constexpr std::uint64_t max() { return std::numeric_limits<std::uint64_t>::max(); }

  // Uniform on [0, 1) with 53 random bits.
  double uniform01();
  double uniform(double lo, double hi);
  // Uniform integer in [0, n), unbiased (Lemire's method); n > 0.
  std::uint64_t below(std::uint64_t n);
  bool bernoulli(double p);
  double exponential(double mean);
  // Standard normal by the Marsaglia polar method (the spare value is kept).
  double normal();
  double normal(double mean, double sigma) { return mean + sigma * normal(); }
  double lognormal(double mu, double sigma);

 private:
  RandomStream() = default;
  std::array<std::uint64_t, 4> s_{};
  double spare_normal_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace covsim
