// covsim.Scenario: a scenario read and validated exactly as `covsim run` reads it, from a file
// or a dict, and changed by dotted path as sweeps change it.
#include "scenario_binding.hpp"

#include <pybind11/stl/filesystem.h>

#include "scenarios/input_file.hpp"
#include "scenarios/scenario_error.hpp"
#include "scenarios/scenario_override.hpp"

namespace covsim::python {

nlohmann::json to_json(const py::handle& o) {
  const py::module_ json = py::module_::import("json");
  // numpy arrays and numpy scalars stand for their lists and numbers (NaN is still refused).
  const py::cpp_function numpy_values([](const py::handle& x) -> py::object {
    if (py::hasattr(x, "tolist")) return x.attr("tolist")();
    throw py::type_error("expected numbers, strings, lists or dicts, found " +
                         py::str(py::type::of(x).attr("__name__")).cast<std::string>());
  });
  return nlohmann::json::parse(
      json.attr("dumps")(o, py::arg("allow_nan") = false, py::arg("default") = numpy_values)
          .cast<std::string>());
}

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

py::object to_python(const nlohmann::ordered_json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

PyScenario PyScenario::from_file(const std::filesystem::path& path) {
  InputFile in = read_input(path);
  PyScenario s;
  s.base_dir = path.parent_path();
  try {
    s.parsed = parse_scenario(in.json, in.source, s.base_dir);
  } catch (const ScenarioError& e) {
    throw in.located(e);
  }
  s.json = std::move(in.json);
  return s;
}

PyScenario PyScenario::from_json(nlohmann::json j, const std::string& source,
                                 const std::filesystem::path& base_dir) {
  PyScenario s;
  s.json = std::move(j);
  s.base_dir = base_dir;
  s.parsed = parse_scenario(s.json, source, base_dir);
  return s;
}

void PyScenario::set(const std::string& path, const nlohmann::json& value) {
  // Errors name the call, not the scenario's file, which was valid before it.
  const std::string call = "set(\"" + path + "\", " + value.dump() + ")";
  if (const std::string e = dotted_path_error(path); !e.empty())
    throw py::value_error(call + ": " + e);
  nlohmann::json j = json;
  try {
    override_scenario(j, path, value);
    parsed = parse_scenario(j, parsed.source, base_dir);  // validated, or nothing changes
  } catch (const ScenarioError& e) {
    if (e.path().empty()) throw ScenarioError(call + ": " + e.what());
    throw ScenarioError(call, e.path(), e.detail());
  }
  json = std::move(j);
}

void bind_scenario(py::module_& m) {
  py::class_<PyScenario>(m, "Scenario",
                         "A scenario, validated as `covsim run` validates it "
                         "(docs/scenario-format.md).")
      .def_static(
          "from_file", &PyScenario::from_file, py::arg("path"),
          "Reads a scenario file (YAML for a name ending in .yaml or .yml, JSON otherwise); "
          "files it names are relative to it.")
      .def_static(
          "from_dict",
          [](const py::dict& d, const std::filesystem::path& base_dir) {
            return PyScenario::from_json(to_json(d), "<dict>", base_dir);
          },
          py::arg("scenario"), py::arg("base_dir") = ".",
          "A scenario from a dict (as its JSON would read); files it names are relative to "
          "base_dir.")
      .def(
          "set",
          [](PyScenario& s, const std::string& path, const py::object& value) -> PyScenario& {
            s.set(path, to_json(value));
            return s;
          },
          py::arg("path"), py::arg("value"),
          "Sets a dotted path ('network.loss.p') to a JSON value, as a sweep does, and "
          "validates the result (raising ScenarioError, with nothing changed, if it is invalid). "
          "Returns the scenario.")
      .def("copy", [](const PyScenario& s) { return s; })
      .def(
          "to_dict", [](const PyScenario& s) { return to_python(s.json); },
          "The scenario's JSON as given (defaults not filled in).")
      .def_property_readonly("source", [](const PyScenario& s) { return s.parsed.source; })
      .def_property_readonly(
          "robots", [](const PyScenario& s) { return to_array(s.parsed.robot_positions); },
          "Start positions, an (n, 2) array [m].")
      .def_property_readonly("seed",
                             [](const PyScenario& s) -> py::object {
                               if (!s.parsed.seed) return py::none();
                               return py::int_(*s.parsed.seed);
                             })
      .def("__repr__", [](const PyScenario& s) {
        return "<covsim.Scenario " + s.parsed.source + ", " +
               std::to_string(s.parsed.robot_positions.size()) + " robots>";
      });
}

}  // namespace covsim::python
