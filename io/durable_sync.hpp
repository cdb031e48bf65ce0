#pragma once
// Flushing to the disk itself (fsync), so that a file or folder renamed into place survives
// a power cut or a crash of the machine, not only of covsim.
#include <filesystem>

namespace covsim {

// fsync of a file or a directory (a directory's entries: the names renamed into it). Throws
// std::runtime_error naming the path on failure.
void sync_to_disk(const std::filesystem::path& path);

}  // namespace covsim
