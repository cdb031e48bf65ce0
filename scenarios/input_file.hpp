#pragma once
// A user's input file (a scenario, a sweep, generators) read whole into JSON: YAML for a name
// ending in .yaml or .yml, JSON otherwise, so that both follow one schema and JsonValue reads
// both. A YAML file keeps where each value starts, so that an error found later, at a JSON
// path, can name its line and column too.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <unordered_map>

#include "scenarios/scenario_error.hpp"

namespace covsim {

struct InputFile {
  nlohmann::json json;
  std::string source;  // the file, as errors name it
  // JSON path ("$.robots.positions[2]") -> where its value starts; empty for JSON.
  std::unordered_map<std::string, TextPlace> places;

  // The place of `path`, or of the nearest value that encloses it; unknown if none has one.
  TextPlace place_of(std::string_view path) const;
  // `e` with the place of its path, when it is an error at a value of this file that has
  // none yet; otherwise `e` as it is.
  ScenarioError located(const ScenarioError& e) const;
};

// Whether a file is read as YAML: its name ends in .yaml or .yml.
bool is_yaml_file(const std::filesystem::path& file);
// Reads a file strictly (parse_json or parse_yaml, by its name). A missing file or a
// directory is a ScenarioError naming it.
InputFile read_input(const std::filesystem::path& file);
// read_input(file).json, for a caller whose errors need no line and column.
nlohmann::json read_input_file(const std::filesystem::path& file);
// A file's whole text; `format` ("JSON", "YAML") names what was expected in errors.
std::string read_text_file(const std::filesystem::path& file, std::string_view format);

}  // namespace covsim
