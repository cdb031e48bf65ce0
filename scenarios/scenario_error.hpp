#pragma once
#include <stdexcept>
#include <string>

namespace covsim {

// A scenario (or other input file) that cannot be used. The message reads
// "FILE: $.json.path: what was expected", or "FILE:LINE:COLUMN: ..." for malformed JSON;
// where the error is at a JSON value, file() and path() name it on their own too.
struct ScenarioError : std::runtime_error {
  using std::runtime_error::runtime_error;
  ScenarioError(std::string file, std::string path, std::string what)
      : std::runtime_error(file + ": " + path + ": " + what),
        file_(std::move(file)),
        path_(std::move(path)),
        detail_(std::move(what)) {}
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }      // "$.network.loss.p"; empty if none
  const std::string& detail() const { return detail_; }  // what was expected, alone

 private:
  std::string file_, path_, detail_;
};

}  // namespace covsim
