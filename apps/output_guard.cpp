#include "apps/output_guard.hpp"

#include "apps/input_error.hpp"

namespace covsim::app {

std::unique_ptr<OutputLock> guard_output(const std::filesystem::path& dir) {
  try {
    return std::make_unique<OutputLock>(dir);
  } catch (const std::runtime_error& e) {  // OutputLocked included
    throw InputError(e.what());
  }
}

}  // namespace covsim::app
