#include "io/atomic_file.hpp"

#include <stdexcept>
#include <system_error>

#include "io/durable_sync.hpp"

namespace covsim {

namespace fs = std::filesystem;

AtomicFile::AtomicFile(fs::path path) : path_(std::move(path)), target_(path_) {
  std::error_code ec;
  // A symbolic link stays one: the file it points to is what is written.
  if (fs::is_symlink(fs::symlink_status(path_, ec))) {
    target_ = fs::weakly_canonical(path_, ec);
    if (ec) throw std::runtime_error(path_.string() + ": cannot follow the link: " + ec.message());
  }
  // A device, a FIFO or a socket (/dev/null, a pipe) is written through, never replaced.
  const fs::file_status st = fs::status(target_, ec);
  through_ = fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st);
  if (!through_) partial_ = target_.string() + ".partial";
  out_.open(through_ ? target_ : partial_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(path_.string() + ": cannot open for writing");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  if (through_) return;
  std::error_code ignored;
  fs::remove(partial_, ignored);
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error(path_.string() + ": write failed");
  out_.close();
  if (through_) {
    committed_ = true;
    return;
  }
  sync_to_disk(partial_);  // on the disk before its name is
  std::error_code ec;
  fs::rename(partial_, target_, ec);
  if (ec) throw std::runtime_error(path_.string() + ": cannot move into place: " + ec.message());
  committed_ = true;
}

}  // namespace covsim
