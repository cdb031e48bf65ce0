// One writer per output folder (io/output_lock): a second lock on the same folder is refused
// at once, naming the folder and the holder's process id; the lock goes with its holder.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/output_lock.hpp"

using namespace covsim;
namespace fs = std::filesystem;

namespace {
fs::path lock_test_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("covsim-lock-" + std::to_string(::getpid())) / name;
  fs::remove_all(dir.parent_path());
  return dir;
}
}  // namespace

TEST_CASE("an output folder has one writer at a time", "[io][lock]") {
  const fs::path dir = lock_test_dir("out") / "run";
  {
    const OutputLock first(dir);
    CHECK(first.path() == dir.parent_path() / ".run.lock");
    CHECK_FALSE(fs::exists(dir));  // nothing in DIR is touched
    std::ifstream in(first.path());
    std::string pid;
    in >> pid;
    CHECK(pid == std::to_string(::getpid()));
    // A second writer, even in this process, is refused at once.
    CHECK_THROWS_AS(OutputLock(dir), OutputLocked);
    CHECK_THROWS_WITH(OutputLock(dir), Catch::StartsWith(dir.string() + ": another covsim") &&
                                           Catch::Contains("(process " + pid + ")") &&
                                           Catch::Contains("nothing was changed"));
    // "DIR/" is DIR.
    CHECK_THROWS_AS(OutputLock(dir.string() + "/"), OutputLocked);
    // Another folder is free.
    CHECK_NOTHROW(OutputLock(dir.parent_path() / "other"));
  }
  // Released with its holder; the lock file stays.
  CHECK(fs::exists(dir.parent_path() / ".run.lock"));
  CHECK_NOTHROW(OutputLock(dir));
  fs::remove_all(dir.parent_path().parent_path());
}

TEST_CASE("an output folder named through a link is locked where the link points", "[io][lock]") {
  const fs::path root = lock_test_dir("linked");
  fs::create_directories(root / "real");
  fs::create_directory_symlink("real", root / "alias");
  const OutputLock held(root / "real");
  CHECK(held.path() == root / ".real.lock");
  CHECK_THROWS_AS(OutputLock(root / "alias"), OutputLocked);
  fs::remove_all(root.parent_path());
}
