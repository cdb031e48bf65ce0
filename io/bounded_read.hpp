#pragma once
// Reads that stop at a stated size. An input named by a user may be /dev/zero, a pipe that
// never ends or a file far larger than any scenario: it is refused with its name once the
// limit is passed, never read until memory runs out.
#include <cstddef>
#include <filesystem>
#include <istream>
#include <stdexcept>
#include <string>

namespace covsim {

// The most a whole-file input (a scenario, a sweep, a raster, a sweep folder's records) may
// hold: far above any real one (a million generators take about 40 MB of JSON).
inline constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

// Thrown with "<file>: <what went wrong>" when a file cannot be opened or read, or is larger
// than the limit.
class InputReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The whole of `file` (regular file, device, pipe); throws InputReadError past `max_bytes`.
std::string read_whole_file(const std::filesystem::path& file,
                            std::size_t max_bytes = kMaxInputBytes);

// std::getline that throws InputReadError (naming `name`) on a line longer than `max_bytes`.
// False at the end of the input with nothing read.
bool read_bounded_line(std::istream& in, std::string& line, std::size_t max_bytes,
                       const std::string& name);

}  // namespace covsim
