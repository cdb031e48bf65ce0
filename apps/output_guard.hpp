#pragma once
// The lock a command holds on its output folder (io/output_lock), a refusal reported as
// bad input (exit 2): another writer holds the folder, or its lock file cannot be made.
#include <filesystem>
#include <memory>

#include "io/output_lock.hpp"

namespace covsim::app {

std::unique_ptr<OutputLock> guard_output(const std::filesystem::path& dir);

}  // namespace covsim::app
