#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace covsim {

// Where a value starts in a text file: 1-based line and column; 0 where unknown.
struct TextPlace {
  std::size_t line = 0, column = 0;
  bool known() const { return line > 0; }
};

// A scenario (or other input file) that cannot be used. The message reads
// "FILE: $.json.path: what was expected", "FILE:LINE:COLUMN: $.json.path: ..." where the
// value's place in the file is known (YAML), or "FILE:LINE:COLUMN: ..." for malformed input;
// where the error is at a JSON value, file(), path() and place() name it on their own too.
struct ScenarioError : std::runtime_error {
  using std::runtime_error::runtime_error;
  ScenarioError(std::string file, std::string path, std::string what)
      : ScenarioError(std::move(file), TextPlace{}, std::move(path), std::move(what)) {}
  ScenarioError(std::string file, TextPlace place, std::string path, std::string what)
      : std::runtime_error(file + located(place) + ": " + path + ": " + what),
        file_(std::move(file)),
        path_(std::move(path)),
        detail_(std::move(what)),
        place_(place) {}
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }      // "$.network.loss.p"; empty if none
  const std::string& detail() const { return detail_; }  // what was expected, alone
  TextPlace place() const { return place_; }             // where the value is, if known

 private:
  static std::string located(TextPlace p) {
    return p.known() ? ":" + std::to_string(p.line) + ":" + std::to_string(p.column) : "";
  }
  std::string file_, path_, detail_;
  TextPlace place_;
};

}  // namespace covsim
