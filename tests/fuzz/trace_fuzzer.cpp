// libFuzzer target: any bytes as a trace file for `covsim replay` and trace comparison. A bad
// trace must end in a TraceFormatError naming the file and line (the CLI's exit 2); a crash,
// a sanitizer report, a hang or any other exception is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/trace.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("covsim-trace-fuzz-" + std::to_string(getpid()));
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    covsim::TraceReader a(file), b(file);
    if (covsim::first_divergence(a, b)) __builtin_trap();  // a trace equals itself
  } catch (const covsim::TraceFormatError&) {
  }
  return 0;
}
