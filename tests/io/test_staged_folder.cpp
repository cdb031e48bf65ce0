#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/staged_folder.hpp"

using namespace covsim;
namespace fs = std::filesystem;

namespace {
void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}
std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
// A folder holding result.txt with `text`.
void folder_with(const fs::path& dir, const std::string& text) {
  fs::create_directories(dir);
  write(dir / "result.txt", text);
}
bool owned(const std::string& name) {
  return name == "result.txt" || name == "figure.svg";
}
fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("covsim-staged-" + name);
  for (const char* suffix : {"", ".partial", ".replaced"})
    fs::remove_all(dir.string() + suffix);
  return dir;
}
}  // namespace

TEST_CASE("a staged folder appears only on commit, whole", "[staged_folder]") {
  const fs::path dir = fresh("new");
  {
    StagedFolder f(dir, owned);
    write(f.path() / "result.txt", "new");
    CHECK_FALSE(fs::exists(dir));
    f.commit();
  }
  CHECK(read(dir / "result.txt") == "new");
  CHECK_FALSE(fs::exists(dir.string() + ".partial"));
  {
    StagedFolder f(dir, owned);  // not committed: nothing changes, nothing is left
    write(f.path() / "result.txt", "lost");
  }
  CHECK(read(dir / "result.txt") == "new");
  CHECK_FALSE(fs::exists(dir.string() + ".partial"));
}

TEST_CASE("a staged folder replaces its own files and carries the others over", "[staged_folder]") {
  const fs::path dir = fresh("replace");
  fs::create_directories(dir / "frames");
  write(dir / "result.txt", "old");
  write(dir / "figure.svg", "old figure");
  write(dir / "notes.txt", "mine");
  write(dir / "frames" / "f1.png", "frame");
  StagedFolder f(dir, owned);
  write(f.path() / "result.txt", "new");
  f.commit();
  CHECK(read(dir / "result.txt") == "new");
  CHECK_FALSE(fs::exists(dir / "figure.svg"));  // the earlier output, not written again
  CHECK(read(dir / "notes.txt") == "mine");
  CHECK(read(dir / "frames" / "f1.png") == "frame");
  CHECK_FALSE(fs::exists(dir.string() + ".partial"));
  CHECK_FALSE(fs::exists(dir.string() + ".replaced"));
}

TEST_CASE("a staged folder recovers what a killed commit left", "[staged_folder]") {
  const fs::path dir = fresh("killed");
  const fs::path replaced = dir.string() + ".replaced", staging = dir.string() + ".partial";
  SECTION("killed between the two renames: the old folder is put back") {
    folder_with(replaced, "old");
    folder_with(staging, "half");
    StagedFolder f(dir, owned);
    CHECK(read(dir / "result.txt") == "old");
    CHECK(fs::is_empty(f.path()));
  }
  SECTION("killed after the new folder was in place: the old one is removed") {
    folder_with(replaced, "old");
    folder_with(dir, "new");
    StagedFolder f(dir, owned);
    CHECK(read(dir / "result.txt") == "new");
    CHECK_FALSE(fs::exists(replaced));
  }
  SECTION("killed between the renames with a user's note carried: the note goes back") {
    folder_with(replaced, "old");
    folder_with(staging, "half");
    write(staging / "notes.txt", "mine");
    StagedFolder f(dir, owned);
    CHECK(read(dir / "result.txt") == "old");
    CHECK(read(dir / "notes.txt") == "mine");
    CHECK(fs::is_empty(f.path()));
  }
  SECTION("killed while carrying, the old folder still in place: the note goes back") {
    folder_with(dir, "old");
    folder_with(staging, "half");
    write(staging / "notes.txt", "mine");
    StagedFolder f(dir, owned);
    CHECK(read(dir / "result.txt") == "old");
    CHECK(read(dir / "notes.txt") == "mine");
  }
  SECTION("a note left in the staging folder whose name DIR has too is refused, both kept") {
    folder_with(dir, "old");
    write(dir / "notes.txt", "new note");
    folder_with(staging, "half");
    write(staging / "notes.txt", "old note");
    CHECK_THROWS_WITH(StagedFolder(dir, owned),
                      Catch::Contains("notes.txt, left by an earlier run"));
    CHECK(read(dir / "notes.txt") == "new note");
    CHECK(read(staging / "notes.txt") == "old note");
  }
  SECTION("a killed first run leaves no folder behind") {
    folder_with(staging, "half");
    StagedFolder f(dir, owned);
    CHECK_FALSE(fs::exists(dir));
  }
}

TEST_CASE("a staged folder refuses a file in its place", "[staged_folder]") {
  const fs::path dir = fresh("file");
  write(dir, "a file");
  CHECK_THROWS_WITH(StagedFolder(dir, owned), Catch::Contains("exists and is not a directory"));
  fs::remove(dir);
}
