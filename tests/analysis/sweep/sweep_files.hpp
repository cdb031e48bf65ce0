#pragma once
// Scratch folders and sweep files for the sweep and sweep-chart tests.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace covsim::test {

// A fresh folder under the temporary directory, named for this process and `name`.
inline std::filesystem::path temp_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() /
                                  ("covsim-sweep-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// DIR/sweep.json holding `body`.
inline std::filesystem::path write_sweep(const std::filesystem::path& dir,
                                         const std::string& body) {
  std::ofstream(dir / "sweep.json") << body;
  return dir / "sweep.json";
}

}  // namespace covsim::test
