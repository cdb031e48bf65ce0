#include "io/bounded_read.hpp"

#include <cstdio>
#include <fstream>
#include <string>

namespace covsim {

namespace {

std::string size_text(std::size_t bytes) {
  return bytes >= (std::size_t{1} << 20) ? std::to_string(bytes >> 20) + " MiB"
                                         : std::to_string(bytes) + " bytes";
}

}  // namespace

std::string read_whole_file(const std::filesystem::path& file, std::size_t max_bytes) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputReadError(file.string() + ": cannot open file");
  std::string text;
  char chunk[1 << 16];
  // Chunks, not the file's size: a device or a pipe has none.
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    const auto got = static_cast<std::size_t>(in.gcount());
    if (text.size() + got > max_bytes)
      throw InputReadError(file.string() + ": larger than " + size_text(max_bytes) +
                           ", more than any input covsim reads");
    text.append(chunk, got);
  }
  if (in.bad()) throw InputReadError(file.string() + ": cannot read file");
  return text;
}

bool read_bounded_line(std::istream& in, std::string& line, std::size_t max_bytes,
                       const std::string& name) {
  line.clear();
  std::streambuf* buf = in.rdbuf();
  for (;;) {
    const int c = buf->sbumpc();
    if (c == EOF) {
      in.setstate(std::ios::eofbit);
      return !line.empty();
    }
    if (c == '\n') return true;
    if (line.size() == max_bytes)
      throw InputReadError(name + ": a line longer than " + size_text(max_bytes));
    line.push_back(static_cast<char>(c));
  }
}

}  // namespace covsim
