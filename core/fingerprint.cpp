#include "core/fingerprint.hpp"

#include <bit>

namespace covsim {

void Fingerprint::fold_state(double x) {
  fold(std::bit_cast<std::uint64_t>(x));
}

void Fingerprint::fold_state(std::span<const double> xs) {
  for (double x : xs)
    fold_state(x);
}

std::string Fingerprint::to_hex(std::uint64_t v) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4)
    s[static_cast<std::size_t>(i)] = kDigits[v & 0xf];
  return s;
}

std::optional<std::uint64_t> Fingerprint::parse_hex(std::string_view text) {
  if (text.size() != 16) return std::nullopt;
  std::uint64_t v = 0;
  for (char c : text) {
    int d;
    if (c >= '0' && c <= '9')
      d = c - '0';
    else if (c >= 'a' && c <= 'f')
      d = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F')
      d = c - 'A' + 10;
    else
      return std::nullopt;
    v = (v << 4) | static_cast<std::uint64_t>(d);
  }
  return v;
}

}  // namespace covsim
