#pragma once
// An output file that appears only when complete: written to "PATH.partial" and renamed
// to PATH by commit(). If the writer is destroyed without commit (an error, an exception),
// the partial file is removed, so a failed run never leaves half-written output behind.
// A path that is a symbolic link has the file it points to written (the link stays); one
// that is a device, a FIFO or a socket (/dev/null, a named pipe) is written through as it
// comes, never replaced by a regular file.
#include <filesystem>
#include <fstream>
#include <string>

namespace covsim {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return out_; }
  // Flushes, checks every write succeeded, syncs to the disk, and renames into place; throws
  // on failure.
  void commit();
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;     // as given, for messages
  std::filesystem::path target_;   // what is written: path_, or where its link points
  std::filesystem::path partial_;  // empty when written through
  std::ofstream out_;
  bool through_ = false;
  bool committed_ = false;
};

}  // namespace covsim
