#pragma once
#include <stdexcept>

namespace covsim::app {

// Bad input from the user (a file, an argument): reported with exit code 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace covsim::app
