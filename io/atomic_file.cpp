#include "io/atomic_file.hpp"

#include <stdexcept>
#include <system_error>

#include "io/durable_sync.hpp"
#include "io/link_target.hpp"

namespace covsim {

namespace fs = std::filesystem;

AtomicFile::AtomicFile(fs::path path) : path_(std::move(path)), target_(path_) {
  std::error_code ec;
  // A device, a FIFO or a socket (/dev/null, /dev/stdout on a pipe), directly or through
  // links, is written through as given, never replaced.
  const fs::file_status st = fs::status(path_, ec);
  through_ = fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st);
  // A symbolic link stays one: the file it points to is what is written, even if it does
  // not exist yet.
  if (!through_) {
    target_ = link_target(path_);
    partial_ = target_.string() + ".partial";
  }
  out_.open(through_ ? path_ : partial_, std::ios::binary | std::ios::trunc);
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
