#pragma once
// One writer per output folder. A run, a sweep or a merge holds an exclusive flock(2) on
// ".DIR.lock", a hidden file beside DIR (out/.run.lock for out/run), for as long as it writes DIR.
// The kernel releases the lock when the process ends, however it ends (kill -9 included), so no
// stale lock outlives its holder; the file itself stays, holding the last holder's process id
// (removing it could let two writers lock two different files of one name).
#include <filesystem>
#include <stdexcept>
#include <string>

namespace covsim {

// Another process holds the folder: what() names the folder and that process.
struct OutputLocked : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class OutputLock {
 public:
  // Takes the lock, creating DIR's parent folders if missing, or throws OutputLocked at once
  // (never waits), before anything in DIR is touched; std::runtime_error if the lock file
  // cannot be made. A DIR named through a symbolic link is locked where the link points.
  explicit OutputLock(const std::filesystem::path& dir);
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  ~OutputLock();

  // The lock file: .DIR.lock beside DIR.
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// The lock file of an output folder.
std::filesystem::path output_lock_path(const std::filesystem::path& dir);

}  // namespace covsim
