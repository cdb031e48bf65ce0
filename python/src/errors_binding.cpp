// covsim.ScenarioError (a ValueError) with the file and JSON path apart: what every invalid
// scenario, sweep or run folder raises.
#include "bindings.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim::python {

void bind_errors(py::module_& m) {
  static py::exception<ScenarioError> error(m, "ScenarioError", PyExc_ValueError);
  error.doc() =
      "An invalid scenario: str(e) reads 'FILE: $.json.path: what was expected'; e.file and "
      "e.path hold the file and the JSON path apart (path is '' where there is none).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ScenarioError& e) {
      py::object instance = py::reinterpret_borrow<py::object>(error)(e.what());
      instance.attr("file") = e.file();
      instance.attr("path") = e.path();
      PyErr_SetObject(error.ptr(), instance.ptr());
    }
  });
}

}  // namespace covsim::python
