#include "io/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "io/link_target.hpp"

namespace covsim {

namespace fs = std::filesystem;

fs::path output_lock_path(const fs::path& dir) {
  fs::path d = link_target(dir.lexically_normal());
  if (!d.has_filename()) d = d.parent_path();  // "out/run/"
  // Hidden, so that a glob of the folders (shard-*) does not take it for one of them.
  return d.parent_path() / ("." + d.filename().string() + ".lock");
}

OutputLock::OutputLock(const fs::path& dir) : path_(output_lock_path(dir)) {
  const std::string folder = dir.lexically_normal().string();
  if (const fs::path parent = path_.parent_path(); !parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec)
      throw std::runtime_error(folder + ": cannot create its folder " + parent.string() + ": " +
                               ec.message());
  }
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error(folder + ": cannot open its lock file " + path_.string() + ": " +
                             std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    char held[32] = {};
    const ssize_t n = ::pread(fd_, held, sizeof held - 1, 0);
    ::close(fd_);
    fd_ = -1;
    if (err != EWOULDBLOCK)
      throw std::runtime_error(folder + ": cannot lock " + path_.string() + ": " +
                               std::strerror(err));
    std::string pid(held, n > 0 ? static_cast<std::size_t>(n) : 0);
    pid.erase(pid.find_last_not_of(" \n") + 1);
    throw OutputLocked(folder + ": another covsim" +
                       (pid.empty() ? std::string() : " (process " + pid + ")") +
                       " is writing this folder (it holds " + path_.string() +
                       "); nothing was changed: wait for it to end, or choose another output "
                       "folder");
  }
  // Ours: the holder's process id, for the message a second writer gets.
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, pid.data(), pid.size(), 0);
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace covsim
