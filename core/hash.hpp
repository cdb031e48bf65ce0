#pragma once
// Small, fixed hash functions. Their outputs feed fingerprints and random-stream keys, so
// they are part of the reproducibility contract: never change them without updating the
// golden fingerprints deliberately.
#include <cstdint>
#include <string_view>

namespace covsim {

// FNV-1a, 64 bit: stable names for event kinds and random-stream purposes.
constexpr std::uint64_t fnv1a64(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

// The 64-bit finaliser of MurmurHash3: a bijection with full avalanche.
constexpr std::uint64_t fmix64(std::uint64_t k) {
  k ^= k >> 33;
  k *= 0xff51afd7ed558ccdULL;
  k ^= k >> 33;
  k *= 0xc4ceb9fe1a85ec53ULL;
  k ^= k >> 33;
  return k;
}

// Order-sensitive combination of a running hash with one more word.
constexpr std::uint64_t hash_combine(std::uint64_t h, std::uint64_t word) {
  return fmix64(h ^ (word * 0x9e3779b97f4a7c15ULL + 0x632be59bd9b4e019ULL));
}

}  // namespace covsim
