#include <catch2/catch.hpp>

#include "core/fingerprint.hpp"

using namespace covsim;

TEST_CASE("fingerprints print as 16 hex digits and parse back", "[fingerprint]") {
  CHECK(Fingerprint::to_hex(0x0123456789abcdefULL) == "0123456789abcdef");
  CHECK(Fingerprint::to_hex(0) == "0000000000000000");
  CHECK(Fingerprint::parse_hex("0123456789ABCDEF") == 0x0123456789abcdefULL);
  CHECK_FALSE(Fingerprint::parse_hex("0123"));
  CHECK_FALSE(Fingerprint::parse_hex("0123456789abcdeg"));
  Fingerprint f;
  CHECK(f.hex().size() == 16);
  CHECK(Fingerprint::parse_hex(f.hex()) == f.value());
}

TEST_CASE("the fingerprint is sensitive to order, kind, entity, time and state", "[fingerprint]") {
  auto events = [](std::int64_t t1, std::uint64_t k1, std::uint32_t e1, std::int64_t t2,
                   std::uint64_t k2, std::uint32_t e2) {
    Fingerprint f;
    f.fold_event(SimTime::from_ns(t1), k1, e1);
    f.fold_event(SimTime::from_ns(t2), k2, e2);
    return f.value();
  };
  const auto base = events(1, 10, 1, 2, 20, 2);
  CHECK(base == events(1, 10, 1, 2, 20, 2));
  CHECK(base != events(2, 20, 2, 1, 10, 1));
  CHECK(base != events(1, 10, 1, 3, 20, 2));
  CHECK(base != events(1, 11, 1, 2, 20, 2));
  CHECK(base != events(1, 10, 1, 2, 20, 3));
  CHECK(base != events(1, 10, 2, 2, 20, 1));

  Fingerprint a, b;
  a.fold_state(0.0);
  b.fold_state(-0.0);
  CHECK(a.value() != b.value());
}
