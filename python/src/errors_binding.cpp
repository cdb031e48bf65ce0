// covsim.ScenarioError (a ValueError) with the file and JSON path apart: what every invalid
// scenario, sweep or run folder raises. An error from a robot's component during a run comes
// out as the exception the component raised (a Python planner's own, say), with a note saying
// which robot, which component and when.
#include "bindings.hpp"
#include "robot/component_error.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim::python {

namespace {

py::exception<ScenarioError>* scenario_error = nullptr;

void set_scenario_error(const ScenarioError& e) {
  py::object instance = py::reinterpret_borrow<py::object>(*scenario_error)(e.what());
  instance.attr("file") = e.file();
  instance.attr("path") = e.path();
  const TextPlace place = e.place();
  instance.attr("line") = place.known() ? py::object(py::int_(place.line)) : py::none();
  instance.attr("column") = place.known() ? py::object(py::int_(place.column)) : py::none();
  PyErr_SetObject(scenario_error->ptr(), instance.ptr());
}

// Sets the Python error the component's exception stands for.
void set_cause(const std::exception_ptr& cause, const std::string& fallback) {
  try {
    std::rethrow_exception(cause);
  } catch (py::error_already_set& e) {
    e.restore();  // raised in Python: as it was
  } catch (const py::builtin_exception& e) {
    e.set_error();  // a ValueError or TypeError of the bindings
  } catch (const ScenarioError& e) {
    set_scenario_error(e);
  } catch (const std::invalid_argument& e) {
    PyErr_SetString(PyExc_ValueError, e.what());
  } catch (const std::out_of_range& e) {
    PyErr_SetString(PyExc_IndexError, e.what());
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  } catch (...) {
    PyErr_SetString(PyExc_RuntimeError, fallback.c_str());
  }
}

}  // namespace

void bind_errors(py::module_& m) {
  static py::exception<ScenarioError> error(m, "ScenarioError", PyExc_ValueError);
  scenario_error = &error;
  error.doc() =
      "An invalid scenario: str(e) reads 'FILE: $.json.path: what was expected' (with "
      "':LINE:COLUMN' after FILE where the value's place is known: YAML files); e.file and "
      "e.path hold the file and the JSON path apart (path is '' where there is none), e.line "
      "and e.column the place (None where unknown).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ScenarioError& e) {
      set_scenario_error(e);
    } catch (const ComponentError& e) {
      const std::exception_ptr cause = e.nested_ptr();
      if (!cause) {
        PyErr_SetString(PyExc_RuntimeError, e.what());
        return;
      }
      set_cause(cause, e.what());
      // The context as a note (Python 3.11), shown under the traceback.
      py::error_already_set raised;
      if (py::hasattr(raised.value(), "add_note")) raised.value().attr("add_note")(e.context());
      raised.restore();
    }
  });
}

}  // namespace covsim::python
