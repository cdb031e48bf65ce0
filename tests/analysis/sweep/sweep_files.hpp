#pragma once
// Scratch folders and sweep files for the sweep and sweep-chart tests.
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/scratch_files.hpp"

namespace covsim::test {

// A fresh folder under the temporary directory for a sweep test.
inline std::filesystem::path temp_dir(const std::string& name) {
  return scratch_dir("sweep-" + name);
}

// DIR/sweep.json holding `body`.
inline std::filesystem::path write_sweep(const std::filesystem::path& dir,
                                         const std::string& body) {
  std::ofstream(dir / "sweep.json") << body;
  return dir / "sweep.json";
}

}  // namespace covsim::test
