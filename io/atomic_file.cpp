#include "io/atomic_file.hpp"

#include <stdexcept>
#include <system_error>

#include "io/durable_sync.hpp"

namespace covsim {

AtomicFile::AtomicFile(std::filesystem::path path)
    : path_(std::move(path)), partial_(path_.string() + ".partial") {
  out_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(path_.string() + ": cannot open for writing");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  std::filesystem::remove(partial_, ignored);
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error(path_.string() + ": write failed");
  out_.close();
  sync_to_disk(partial_);  // on the disk before its name is
  std::error_code ec;
  std::filesystem::rename(partial_, path_, ec);
  if (ec) throw std::runtime_error(path_.string() + ": cannot move into place: " + ec.message());
  committed_ = true;
}

}  // namespace covsim
