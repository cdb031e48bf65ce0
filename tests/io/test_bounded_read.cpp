// Bounded reads (io/bounded_read): a whole file up to its limit, refused past it with its
// name; lines as std::getline gives them, refused when one is longer than its limit. An
// endless device (/dev/zero) ends in the error, not in memory exhaustion.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/bounded_read.hpp"
#include "tests/scratch_files.hpp"

namespace fs = std::filesystem;
using covsim::InputReadError;
using covsim::read_bounded_line;
using covsim::read_whole_file;
using covsim::test::scratch_dir;

TEST_CASE("a whole file is read up to its limit and refused past it", "[bounded_read]") {
  const fs::path d = scratch_dir("bounded");
  const std::string text(100'000, 'x');  // more than one chunk
  std::ofstream(d / "a.txt") << text;
  CHECK(read_whole_file(d / "a.txt") == text);
  CHECK(read_whole_file(d / "a.txt", text.size()) == text);
  CHECK_THROWS_WITH(
      read_whole_file(d / "a.txt", text.size() - 1),
      Catch::Contains((d / "a.txt").string()) && Catch::Contains("larger than 99999 bytes"));
  std::ofstream(d / "empty.txt");
  CHECK(read_whole_file(d / "empty.txt").empty());
  CHECK_THROWS_AS(read_whole_file(d / "missing.txt"), InputReadError);
  CHECK_THROWS_WITH(read_whole_file("/dev/zero", 1 << 20),
                    Catch::Contains("/dev/zero: larger than 1 MiB"));
}

TEST_CASE("lines are read as getline reads them, and a line past its limit is refused",
          "[bounded_read]") {
  std::istringstream in("one\n\nthree");
  std::string line;
  REQUIRE(read_bounded_line(in, line, 5, "in"));
  CHECK(line == "one");
  REQUIRE(read_bounded_line(in, line, 5, "in"));
  CHECK(line.empty());
  REQUIRE(read_bounded_line(in, line, 5, "in"));
  CHECK(line == "three");
  CHECK_FALSE(read_bounded_line(in, line, 5, "in"));
  CHECK(in.eof());

  std::istringstream exact("12345\n123456\n");
  REQUIRE(read_bounded_line(exact, line, 5, "exact"));
  CHECK(line == "12345");
  CHECK_THROWS_WITH(read_bounded_line(exact, line, 5, "exact"),
                    "exact: a line longer than 5 bytes");

  std::ifstream zero("/dev/zero", std::ios::binary);
  CHECK_THROWS_WITH(read_bounded_line(zero, line, 1 << 20, "/dev/zero"),
                    "/dev/zero: a line longer than 1 MiB");
}
