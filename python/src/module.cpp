// covsim._covsim: the compiled half of the Python package `covsim` (python/covsim/).
#include "bindings.hpp"
#include "core/version.hpp"

PYBIND11_MODULE(_covsim, m) {
  m.doc() = "covsim's C++ core; use the package `covsim`.";
  m.attr("__version__") = covsim::kVersion;
  covsim::python::bind_errors(m);
  covsim::python::bind_scenario(m);
  covsim::python::bind_geometry(m);
  covsim::python::bind_simulation(m);
  covsim::python::bind_components(m);
  covsim::python::bind_sweep(m);
}
