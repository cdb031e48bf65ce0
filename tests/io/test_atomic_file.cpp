// AtomicFile (io/atomic_file): whole or absent for a regular file; a symbolic link kept as a
// link with its target written; a FIFO (as a device) written through, never replaced.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/atomic_file.hpp"
#include "tests/scratch_files.hpp"

namespace fs = std::filesystem;
using covsim::AtomicFile;
using covsim::test::file_text;
using covsim::test::scratch_dir;

TEST_CASE("a regular file appears only when committed", "[atomic_file]") {
  const fs::path d = scratch_dir("regular");
  {
    AtomicFile f(d / "a.txt");
    f.stream() << "one";
    CHECK_FALSE(fs::exists(d / "a.txt"));
  }
  CHECK_FALSE(fs::exists(d / "a.txt"));
  CHECK_FALSE(fs::exists(d / "a.txt.partial"));
  AtomicFile f(d / "a.txt");
  f.stream() << "two";
  f.commit();
  CHECK(file_text(d / "a.txt") == "two");
}

TEST_CASE("a symbolic link stays a link; the file it points to is written", "[atomic_file]") {
  const fs::path d = scratch_dir("link");
  std::ofstream(d / "target.txt") << "old";
  fs::create_symlink("target.txt", d / "link.txt");
  AtomicFile f(d / "link.txt");
  f.stream() << "new";
  f.commit();
  CHECK(fs::is_symlink(fs::symlink_status(d / "link.txt")));
  CHECK(file_text(d / "target.txt") == "new");
  CHECK_FALSE(fs::exists(d / "link.txt.partial"));
}

TEST_CASE("a dangling symbolic link stays a link; the file it names is created", "[atomic_file]") {
  const fs::path d = scratch_dir("dangling");
  fs::create_directories(d / "sub");
  fs::create_symlink("sub/later.txt", d / "link.txt");
  AtomicFile f(d / "link.txt");
  f.stream() << "made";
  f.commit();
  CHECK(fs::is_symlink(fs::symlink_status(d / "link.txt")));
  CHECK(file_text(d / "sub" / "later.txt") == "made");
}

TEST_CASE("a FIFO is written through, not replaced by a regular file", "[atomic_file]") {
  const fs::path d = scratch_dir("fifo");
  const fs::path fifo = d / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // The read end opened first without blocking: if the FIFO were replaced, the test reads
  // nothing and fails instead of waiting for a writer for ever.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  REQUIRE(reader >= 0);
  {
    AtomicFile f(fifo);
    f.stream() << "through the pipe";
    f.commit();
  }
  char buffer[64] = {};
  const ssize_t n = ::read(reader, buffer, sizeof buffer);
  ::close(reader);
  CHECK(std::string(buffer, n > 0 ? static_cast<std::size_t>(n) : 0) == "through the pipe");
  CHECK(fs::is_fifo(fs::status(fifo)));
  CHECK_FALSE(fs::exists(d / "pipe.partial"));
}
