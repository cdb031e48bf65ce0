#include "io/staged_folder.hpp"

#include <fcntl.h>
#include <linux/fs.h>  // RENAME_EXCHANGE
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "io/durable_sync.hpp"
#include "io/link_target.hpp"

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

// Why `entry` could not be renamed into `into` (a folder on `into_device`), or "" if it can:
// rename cannot cross file systems (a mount point), and moving a folder rewrites its "..".
std::string why_unmovable(const fs::path& entry, dev_t into_device) {
  struct stat st {};
  if (::lstat(entry.c_str(), &st) != 0) return std::strerror(errno);
  if (st.st_dev != into_device) return "it is on another file system (a mount point?)";
  if (S_ISDIR(st.st_mode) && ::access(entry.c_str(), W_OK) != 0)
    return "it is a folder covsim may not move (not writable)";
  return "";
}
}  // namespace

std::vector<std::string> StagedFolder::entries_to_carry() const {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::is_directory(dir_, ec)) return names;
  struct stat staging {};
  if (::stat(staging_.c_str(), &staging) != 0)
    throw std::runtime_error(staging_.string() + ": " + std::strerror(errno));
  for (const auto& entry : fs::directory_iterator(dir_)) {
    const std::string name = entry.path().filename().string();
    if (owned_(name) || fs::exists(staging_ / name)) continue;
    if (const std::string why = why_unmovable(entry.path(), staging.st_dev); !why.empty())
      throw std::invalid_argument(dir_.string() + ": holds " + name +
                                  ", which is not covsim's and cannot be kept in the new "
                                  "output (" +
                                  why +
                                  "); nothing was changed: move it away or choose another "
                                  "output folder");
    names.push_back(name);
  }
  return names;
}

StagedFolder::StagedFolder(fs::path dir, std::function<bool(const std::string&)> owned)
    : dir_(link_target(std::move(dir))),  // a link to a folder stays; the folder is replaced
      staging_(dir_.string() + ".partial"),
      replaced_(dir_.string() + ".replaced"),
      owned_(std::move(owned)) {
  std::error_code ec;
  // A mount point cannot be renamed: refused before anything is touched.
  struct stat self {
  }, parent{};
  if (::stat(dir_.c_str(), &self) == 0 && S_ISDIR(self.st_mode) &&
      ::stat(parent_of(dir_).c_str(), &parent) == 0 && self.st_dev != parent.st_dev)
    throw std::invalid_argument(dir_.string() +
                                ": is a mount point, which covsim cannot replace with the new "
                                "output; nothing was changed: choose a folder inside it");
  // What a killed run left: an old folder not yet removed (DIR itself is then the complete
  // new one, or, if DIR is missing, the old one is put back) and a staging folder, which may
  // hold a user's entries carried into it: those go back into DIR before it is removed.
  if (fs::exists(replaced_, ec)) {
    if (!fs::exists(dir_, ec))
      fs::rename(replaced_, dir_, ec);
    else
      fs::remove_all(replaced_, ec);
  }
  if (fs::is_directory(staging_, ec)) {
    std::vector<std::string> users;
    for (const auto& entry : fs::directory_iterator(staging_, ec)) {
      const std::string name = entry.path().filename().string();
      if (!owned_(name)) users.push_back(name);
    }
    if (!users.empty() && !fs::exists(dir_, ec)) fs::create_directory(dir_, ec);
    for (const std::string& name : users) {
      const fs::path entry = staging_ / name;
      if (fs::exists(dir_ / name))
        throw std::invalid_argument(staging_.string() + " holds " + name +
                                    ", left by an earlier run, and " + dir_.string() +
                                    " has an entry of that name: move one of them away first");
      fs::rename(entry, dir_ / name, ec);
      if (ec)
        throw std::invalid_argument(staging_.string() + " holds " + name +
                                    ", left by an earlier run, which cannot be put back in " +
                                    dir_.string() + ": " + ec.message());
    }
  }
  fs::remove_all(staging_, ec);
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    throw std::invalid_argument(dir_.string() + ": exists and is not a directory");
  fs::create_directories(staging_, ec);
  if (ec)
    throw std::invalid_argument(dir_.string() + ": cannot create directory " + staging_.string() +
                                ": " + ec.message());
  // A user's entry that could not be carried over refuses the folder now, before the work.
  try {
    (void)entries_to_carry();
  } catch (...) {
    fs::remove_all(staging_, ec);
    throw;
  }
}

StagedFolder::~StagedFolder() {
  if (committed_ || stranded_) return;  // stranded: a user's entry is still in it
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
    // Carry over what is not this folder's output, every entry checked first; put back what
    // was carried if anything after fails.
    const std::vector<std::string> to_carry = entries_to_carry();
    std::vector<std::string> carried;
    fs::path old;  // where the old folder is once the new one is in place
    try {
      for (const std::string& name : to_carry) {
        fs::rename(dir_ / name, staging_ / name);
        carried.push_back(name);
      }
      if (!carried.empty()) sync_to_disk(staging_);  // the carried names, before the swap
      if (exchange(staging_, dir_)) {
        old = staging_;
      } else {
        fs::rename(dir_, replaced_);
        fs::rename(staging_, dir_);
        old = replaced_;
      }
    } catch (const std::exception& e) {
      std::error_code ignored;
      if (!fs::exists(dir_, ignored)) fs::rename(replaced_, dir_, ignored);
      std::string left;
      for (const std::string& name : carried) {
        std::error_code ec;
        fs::rename(staging_ / name, dir_ / name, ec);
        if (ec) left += (left.empty() ? "" : ", ") + name;
      }
      if (left.empty()) throw;
      stranded_ = true;  // never removed with the user's entries in it
      throw std::runtime_error(std::string(e.what()) + "; " + left + " could not be put back in " +
                               dir_.string() + " and are in " + staging_.string() +
                               " (the next run into it puts them back)");
    }
    // The new folder is in place: an old one that cannot be removed now (holding only this
    // kind of folder's output) is left for the next run to clean, not a failed commit.
    std::error_code ignored;
    fs::remove_all(old, ignored);
  }
  sync_to_disk(parent_of(dir_));
  committed_ = true;
}

}  // namespace covsim
