#pragma once
// What the Python Scenario holds: the JSON as given (so that `set` can change a dotted path
// and validate again) and the parsed scenario.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "bindings.hpp"
#include "scenarios/scenario.hpp"

namespace covsim::python {

struct PyScenario {
  nlohmann::json json;
  std::filesystem::path base_dir;
  Scenario parsed;

  static PyScenario from_file(const std::filesystem::path& path);
  static PyScenario from_json(nlohmann::json j, const std::string& source,
                              const std::filesystem::path& base_dir);
  void set(const std::string& path, const nlohmann::json& value);
};

nlohmann::json to_json(const py::handle& o);
py::object to_python(const nlohmann::json& j);
py::object to_python(const nlohmann::ordered_json& j);

}  // namespace covsim::python
