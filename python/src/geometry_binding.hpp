#pragma once
#include <memory>

#include "bindings.hpp"
#include "geometry/environment.hpp"

namespace covsim::python {

// Ω as Python sees it; shares the environment it views.
struct PyEnvironment {
  std::shared_ptr<const Environment> env;
};

}  // namespace covsim::python
