#include <fmt/format.h>
#include <zlib.h>
#include <catch2/catch.hpp>

#include <unistd.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>

#include "analysis/records/run_files.hpp"
#include "analysis/records/run_recorder.hpp"
#include "sim/coverage_run.hpp"

using namespace covsim;
namespace fs = std::filesystem;

namespace {

// What trajectory.csv's rows were before TrajectoryRowFormat: fmt's run-time "{}".
std::string reference_row(const TrajectoryRow& r) {
  return fmt::format("{},{},{},{},{},{},{},{},{},{}\n", r.t, r.robot, r.position.x, r.position.y,
                     r.virtual_generator.x, r.virtual_generator.y, r.virtual_target.x,
                     r.virtual_target.y, r.real_target.x, r.real_target.y);
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  REQUIRE(in);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A whole gzip stream inflated with zlib on its own (not through the code under test).
std::string gunzip(const std::string& gz) {
  z_stream z{};
  REQUIRE(inflateInit2(&z, 15 + 16) == Z_OK);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(gz.data()));
  z.avail_in = static_cast<uInt>(gz.size());
  std::string out;
  char chunk[1 << 15];
  int rc = Z_OK;
  while (rc == Z_OK) {
    z.next_out = reinterpret_cast<Bytef*>(chunk);
    z.avail_out = sizeof chunk;
    rc = inflate(&z, Z_NO_FLUSH);
    out.append(chunk, sizeof chunk - z.avail_out);
  }
  const bool whole = rc == Z_STREAM_END && z.avail_in == 0;
  inflateEnd(&z);
  REQUIRE(whole);
  return out;
}

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("covsim-recorder-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("trajectory rows are the bytes fmt's \"{}\" writes, for any double",
          "[recorder][format]") {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> tricky{0.1,
                                   0.0,
                                   -0.0,
                                   1e-300,
                                   1.0 / 3,
                                   -2.0 / 3,
                                   1e22,
                                   1e23,
                                   5e-324,
                                   -5e-324,
                                   2.2250738585072014e-308,  // the smallest normal
                                   2.225073858507201e-308,   // the largest denormal
                                   1.7976931348623157e308,
                                   -1.7976931348623157e308,
                                   1e15,
                                   1e16,
                                   9007199254740994.0,
                                   9999999999999998.0,
                                   123456789012345680.0,
                                   0.0001,
                                   0.00001,
                                   0.000123456789012345,
                                   100000,
                                   1234567.125,
                                   3.3000000000000003,
                                   4.9999999999057145,
                                   inf,
                                   -inf,
                                   std::nan("")};
  TrajectoryRowFormat format;
  std::string ours, expected;
  const auto check = [&](const TrajectoryRow& r) {
    format.append(ours, r);
    expected += reference_row(r);
  };
  for (double a : tricky)
    for (double b : tricky)
      check({a, 7, {a, b}, {b, a}, {a, a}, {b, b}});
  // Equal points and equal times are written once and copied: +0 and -0 must not be taken
  // for each other.
  check({0.0, 0, {0.0, 0.0}, {0.0, 0.0}, {-0.0, 0.0}, {-0.0, 0.0}});
  check({-0.0, 1, {0.0, -0.0}, {0.0, -0.0}, {0.0, -0.0}, {0.0, 0.0}});
  check({-0.0, 4294967295u, {1, 2}, {1, 2}, {1, 2}, {1, 2}});
  check({0.0, 3, {1, 2}, {1, 2}, {2, 1}, {1, 2}});
  // Every exponent: random bit patterns, and decimals of a few digits as the runs write.
  std::mt19937_64 random(17);
  std::uniform_int_distribution<int> digits(0, 17), scale(-20, 20);
  const auto draw = [&] {
    if (random() % 2) return std::bit_cast<double>(random());
    return std::round(static_cast<double>(random() % 1000000000) / std::pow(10.0, digits(random))) *
           std::pow(10.0, scale(random));
  };
  double t = 0.0;
  for (int i = 0; i < 50000; ++i) {
    if (i % 7 == 0) t = draw();
    const Vec2 p{draw(), draw()}, v = i % 3 ? p : Vec2{draw(), draw()};
    const Vec2 vt = i % 2 ? v : Vec2{draw(), draw()}, rt = i % 5 ? vt : Vec2{draw(), draw()};
    check({t, static_cast<std::uint32_t>(random()), p, v, vt, rt});
  }
  REQUIRE(ours.size() == expected.size());
  CHECK(ours == expected);
}

TEST_CASE("a gzip stream written in pieces inflates to what was written", "[recorder][gzip]") {
  std::mt19937_64 random(3);
  std::string data;
  // Random bytes (deflate cannot shrink them: the output fills several chunks) and a long
  // repetitive run.
  for (int i = 0; i < 300000; ++i)
    data += static_cast<char>(random());
  data += std::string(500000, 'x');
  std::ostringstream out;
  GzipWriter gz(out);
  for (std::size_t at = 0; at < data.size();) {
    const std::size_t n = std::min<std::size_t>(data.size() - at, random() % 100000);
    gz.write(std::string_view(data).substr(at, n));
    at += n;
  }
  gz.finish();
  gz.finish();  // once is enough: the trailer is not written twice
  const std::string bytes = out.str();
  REQUIRE(bytes.size() > 2);
  CHECK(static_cast<unsigned char>(bytes[0]) == 0x1f);  // gzip's magic number
  CHECK(static_cast<unsigned char>(bytes[1]) == 0x8b);
  CHECK(gunzip(bytes) == data);

  std::ostringstream empty;
  GzipWriter nothing(empty);
  nothing.finish();
  CHECK(gunzip(empty.str()).empty());
}

TEST_CASE("a compressed recording is the uncompressed one's bytes, gzipped", "[recorder][gzip]") {
  const Scenario s = load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/u_shape.json");
  fs::path dirs[2];
  for (bool compress : {false, true}) {
    fs::path& dir = dirs[compress];
    dir = scratch(compress ? "gz" : "csv");
    RunRecorder recorder(dir, s.robot_positions, RecordingConfig{0.0, compress});
    run_coverage(s, &recorder);
    recorder.commit();
  }
  const std::string csv = read_bytes(dirs[0] / "trajectory.csv");
  const std::string gz = read_bytes(dirs[1] / "trajectory.csv.gz");
  CHECK(csv.rfind("t,robot,x,y,vx,vy,tx,ty,rx,ry\n", 0) == 0);
  CHECK(csv.size() > (1 << 17));  // several buffers' worth: deflated as they were flushed
  CHECK(gz.size() < csv.size() / 3);
  CHECK(gunzip(gz) == csv);
  // Nothing else differs, and nothing is left over.
  CHECK(read_bytes(dirs[0] / "metrics.csv") == read_bytes(dirs[1] / "metrics.csv"));
  // The columns' units beside each table (CSVW), in the header's order.
  for (const fs::path& table :
       {dirs[0] / "trajectory.csv", dirs[1] / "trajectory.csv.gz", dirs[0] / "metrics.csv"}) {
    INFO(table);
    const auto meta = nlohmann::json::parse(read_bytes(table.string() + "-metadata.json"));
    CHECK(meta["url"] == table.filename().string());
    std::string header;
    std::map<std::string, std::string> unit;
    for (const auto& c : meta["tableSchema"]["columns"]) {
      header += (header.empty() ? "" : ",") + c["name"].get<std::string>();
      unit[c["name"]] = c.value("schema:unitText", "");
    }
    const std::string first = table.extension() == ".gz" ? csv : read_bytes(table);
    CHECK(first.rfind(header + "\n", 0) == 0);
    CHECK(unit["t"] == "s");
    if (table.filename() != "metrics.csv") CHECK(unit["x"] == "m");
  }
  CHECK_FALSE(fs::exists(dirs[1] / "trajectory.csv"));
  CHECK_FALSE(fs::exists(dirs[1] / "trajectory.csv.gz.partial"));
  for (const fs::path& d : dirs)
    fs::remove_all(d);
}

TEST_CASE("an uncommitted compressed recording leaves nothing", "[recorder][gzip]") {
  const Scenario s = load_scenario(std::string(COVSIM_SOURCE_DIR) + "/scenarios/u_shape.json");
  const fs::path dir = scratch("abandoned");
  {
    RunRecorder recorder(dir, s.robot_positions, RecordingConfig{0.0, true});
    run_coverage(s, &recorder);
  }
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("a run folder's outputs include both trajectory files", "[recorder][files]") {
  CHECK(is_record_file("trajectory.csv"));
  CHECK(is_record_file("trajectory.csv.gz"));
  CHECK(is_record_file("trajectory.csv.gz.partial"));
  CHECK_FALSE(is_record_file("trajectory.csv.bz2"));
  CHECK_FALSE(is_record_file("notes.txt"));
  CHECK(is_record_file("metrics.csv-metadata.json"));
  CHECK(is_record_file("trajectory.csv.gz-metadata.json"));
  CHECK_FALSE(is_record_file("scene.svg"));  // a figure: analysis/figures' is_run_output
  CHECK(trajectory_file_name(false) == "trajectory.csv");
  CHECK(trajectory_file_name(true) == "trajectory.csv.gz");
}
