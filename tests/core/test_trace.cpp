#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/kernel_example.hpp"
#include "core/trace.hpp"
#include "tests/scratch_files.hpp"

using namespace covsim;
namespace fs = std::filesystem;
using covsim::test::file_text;
using covsim::test::scratch_dir;

namespace {

KernelExampleResult traced_run(const fs::path& file, std::uint64_t seed) {
  Kernel k(seed);
  TraceHeader header;
  header.seed = seed;
  header.scenario_hash = 0xfeedfacecafebeefULL;
  header.entries = {{"note", "kernel example, 4 entities"}};
  TraceWriter w(file, header);
  k.attach_trace(&w);
  const auto r = run_kernel_example(k, {4, SimTime::from_seconds(3.0)});
  w.commit();
  return r;
}

}  // namespace

TEST_CASE("a trace round-trips: header, one record per event, running fingerprint", "[trace]") {
  const fs::path dir = scratch_dir("trace-roundtrip");
  const auto r = traced_run(dir / "a.trace", 9);
  TraceReader reader(dir / "a.trace");
  CHECK(reader.header().seed == 9);
  CHECK(reader.header().scenario_hash == 0xfeedfacecafebeefULL);
  REQUIRE(reader.header().entries.size() == 1);
  CHECK(reader.header().entries[0].second == "kernel example, 4 entities");
  std::uint64_t n = 0, last_fp = 0;
  SimTime last_t;
  while (auto rec = reader.next()) {
    CHECK(rec->index == n);
    CHECK(rec->time >= last_t);
    last_t = rec->time;
    last_fp = rec->fingerprint;
    ++n;
  }
  CHECK(n == r.events);
  CHECK(n > 100);
  CHECK(last_fp != 0);
  CHECK_FALSE(fs::exists(dir / "a.trace.partial"));
}

TEST_CASE("each record carries the fingerprint its handler sees", "[trace]") {
  const fs::path dir = scratch_dir("trace-fingerprints");
  std::vector<std::uint64_t> seen;
  {
    Kernel k(3);
    TraceWriter w(dir / "f.trace", TraceHeader{});
    k.attach_trace(&w);
    const EventKind tick = k.add_kind("tick", [&](Kernel& kk, const Event&) {
      seen.push_back(kk.fingerprint().value());
      kk.fingerprint().fold_state(static_cast<double>(seen.size()));
    });
    k.schedule_periodic(Period::from_ns(7), SimTime::zero(), tick, 1);
    k.schedule_periodic(Period::from_ns(5), SimTime::zero(), tick, 2);
    k.run_until(SimTime::from_ns(100));
    w.commit();
  }
  TraceReader reader(dir / "f.trace");
  std::vector<std::uint64_t> recorded;
  while (auto rec = reader.next())
    recorded.push_back(rec->fingerprint);
  CHECK(recorded.size() == 36);
  CHECK(recorded == seen);
}

TEST_CASE("comparing traces finds the first diverging event", "[trace]") {
  const fs::path dir = scratch_dir("trace-diverge");
  traced_run(dir / "a.trace", 9);
  traced_run(dir / "b.trace", 9);
  {
    TraceReader a(dir / "a.trace"), b(dir / "b.trace");
    CHECK_FALSE(first_divergence(a, b));
  }
  // Alter one record's time in a copy: the divergence is at exactly that record.
  std::string text = file_text(dir / "a.trace");
  const std::size_t events_at = text.find("\nevents\n") + 8;
  std::size_t line_start = events_at;
  for (int i = 0; i < 57; ++i)
    line_start = text.find('\n', line_start) + 1;
  const std::size_t time_start = text.find(' ', line_start) + 1;
  text.insert(time_start, "1");  // the time gains a leading digit
  std::ofstream(dir / "c.trace") << text;
  TraceReader a(dir / "a.trace"), c(dir / "c.trace");
  const auto d = first_divergence(a, c);
  REQUIRE(d);
  CHECK(d->index == 57);
  REQUIRE(d->a);
  REQUIRE(d->b);
  CHECK(d->a->time != d->b->time);
  CHECK(d->a->kind == d->b->kind);

  // A different seed diverges early; a truncated trace is reported as cut short, not as a
  // divergence, and an end record that disagrees with the events as edited.
  traced_run(dir / "d.trace", 10);
  TraceReader a2(dir / "a.trace"), d2(dir / "d.trace");
  CHECK(first_divergence(a2, d2));
  std::string cut = file_text(dir / "a.trace");
  cut.resize(cut.find('\n', events_at) + 1);  // header and one record
  std::ofstream(dir / "e.trace") << cut;
  TraceReader a3(dir / "a.trace"), e3(dir / "e.trace");
  CHECK_THROWS_AS(first_divergence(a3, e3), TraceFormatError);
  TraceReader e4(dir / "e.trace");
  CHECK(e4.next());
  CHECK_THROWS_WITH(e4.next(),
                    Catch::Contains("cut short: it ends after 1 events without its end record"));
  std::string edited = file_text(dir / "a.trace");
  const std::size_t end_at = edited.rfind("\nend ") + 5;
  edited.insert(end_at, "1");  // the count gains a leading digit
  std::ofstream(dir / "f.trace") << edited;
  TraceReader a5(dir / "a.trace"), f5(dir / "f.trace");
  CHECK_THROWS_WITH(first_divergence(a5, f5), Catch::Contains("the trace was edited"));
}

TEST_CASE("malformed traces are reported with file and line", "[trace]") {
  const fs::path dir = scratch_dir("trace-malformed");
  auto expect_error = [&](const std::string& text, const std::string& fragment) {
    std::ofstream(dir / "bad.trace") << text;
    try {
      TraceReader r(dir / "bad.trace");
      while (r.next()) {
      }
      FAIL("no error for: " << text);
    } catch (const std::runtime_error& e) {
      const std::string msg = e.what();
      CHECK_THAT(msg, Catch::Contains("bad.trace:"));
      CHECK_THAT(msg, Catch::Contains(fragment));
    }
  };
  expect_error("nonsense\n", "covsim-trace");
  expect_error("covsim-trace 2\n", "version");
  expect_error("covsim-trace 1\nseed 1\n", "events");
  expect_error("covsim-trace 1\nseed x\nscenario_hash 0000000000000000\nevents\n", "seed");
  expect_error("covsim-trace 1\nseed 1\nevents\n", "scenario_hash");
  expect_error("covsim-trace 1\nseed 1\nscenario_hash 0000000000000000\nevents\n0 5 tick\n",
               ":5: malformed");
  // A header key twice, and a record numbered out of order: edited, not a divergence.
  expect_error("covsim-trace 1\nseed 1\nseed 2\nscenario_hash 0000000000000000\nevents\n",
               ":3: the header has 'seed' twice");
  expect_error("covsim-trace 1\nseed 1\nscenario_hash 0000000000000000\nnote a\nnote b\nevents\n",
               ":5: the header has 'note' twice");
  expect_error(
      "covsim-trace 1\nseed 1\nscenario_hash 0000000000000000\nevents\n"
      "0 5 tick 1 0000000000000001\n2 7 tick 1 0000000000000002\n",
      ":6: event record 1 is numbered 2: the trace was edited");
  expect_error("covsim-trace 1\nseed 1\nscenario_hash 0000000000000000\nevents\n0 5 tick 1 12\n",
               "fingerprint");
}

TEST_CASE("an uncommitted trace leaves no file behind", "[trace]") {
  const fs::path dir = scratch_dir("trace-uncommitted");
  {
    TraceWriter w(dir / "x.trace", TraceHeader{});
    w.record(0, SimTime::from_ns(1), "tick", 0, 1);
    CHECK(fs::exists(dir / "x.trace.partial"));
  }
  CHECK_FALSE(fs::exists(dir / "x.trace"));
  CHECK_FALSE(fs::exists(dir / "x.trace.partial"));
}
