#include "io/staged_folder.hpp"

#include <fcntl.h>
#include <linux/fs.h>  // RENAME_EXCHANGE
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "io/durable_sync.hpp"

namespace covsim {

namespace fs = std::filesystem;

namespace {
// Atomically swaps two paths; false when the file system cannot (errno ENOSYS or EINVAL).
bool exchange(const fs::path& a, const fs::path& b) {
  const long rc = ::syscall(SYS_renameat2, AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(),
                            static_cast<unsigned>(RENAME_EXCHANGE));
  if (rc == 0) return true;
  if (errno == ENOSYS || errno == EINVAL) return false;
  throw std::runtime_error(b.string() + ": cannot exchange with " + a.string() + ": " +
                           std::strerror(errno));
}

fs::path parent_of(const fs::path& p) {
  return p.has_parent_path() ? p.parent_path() : fs::path(".");
}
}  // namespace

StagedFolder::StagedFolder(fs::path dir, std::function<bool(const std::string&)> owned)
    : dir_(std::move(dir)),
      staging_(dir_.string() + ".partial"),
      replaced_(dir_.string() + ".replaced"),
      owned_(std::move(owned)) {
  std::error_code ec;
  // What a killed run left: a staging folder, or an old folder not yet removed (DIR itself
  // is then the complete new one, or, if DIR is missing, the old one is put back).
  fs::remove_all(staging_, ec);
  if (fs::exists(replaced_, ec)) {
    if (!fs::exists(dir_, ec))
      fs::rename(replaced_, dir_, ec);
    else
      fs::remove_all(replaced_, ec);
  }
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    throw std::invalid_argument(dir_.string() + ": exists and is not a directory");
  fs::create_directories(staging_, ec);
  if (ec)
    throw std::invalid_argument(dir_.string() + ": cannot create directory " + staging_.string() +
                                ": " + ec.message());
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void StagedFolder::commit() {
  for (const auto& entry : fs::directory_iterator(staging_)) {
    if (entry.is_regular_file()) sync_to_disk(entry.path());
  }
  sync_to_disk(staging_);
  if (!fs::exists(dir_)) {
    fs::rename(staging_, dir_);
  } else {
    // Carry over what is not this folder's output; put it back if the swap fails.
    std::vector<std::string> carried;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      if (owned_(name) || fs::exists(staging_ / name)) continue;
      fs::rename(entry.path(), staging_ / name);
      carried.push_back(name);
    }
    try {
      if (exchange(staging_, dir_)) {
        fs::remove_all(staging_);  // now the old folder
      } else {
        fs::rename(dir_, replaced_);
        fs::rename(staging_, dir_);
        fs::remove_all(replaced_);
      }
    } catch (...) {
      std::error_code ignored;
      if (!fs::exists(dir_, ignored)) fs::rename(replaced_, dir_, ignored);
      for (const std::string& name : carried)
        fs::rename(staging_ / name, dir_ / name, ignored);
      throw;
    }
  }
  sync_to_disk(parent_of(dir_));
  committed_ = true;
}

}  // namespace covsim
