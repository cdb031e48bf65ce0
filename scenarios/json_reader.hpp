#pragma once
// Reading JSON input with errors that point at the place: every value is reached through a
// JsonValue that knows its file and JSON path, and every failure throws ScenarioError
// "FILE: $.path: expected ...".
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec2.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim {

// JSON nested deeper than this is refused (it would exhaust the stack).
inline constexpr std::size_t kMaxJsonDepth = 256;

// Parses JSON text strictly: malformed JSON (with its line and column), a duplicate key in
// an object, nesting deeper than kMaxJsonDepth, and a number beyond a double's range are
// ScenarioErrors naming `source` (and the JSON path or the place).
nlohmann::json parse_json(const std::string& text, const std::string& source);
// parse_json of a file's text; a missing file or a directory is named as such.
nlohmann::json read_json_file(const std::filesystem::path& file);

class JsonValue {
 public:
  JsonValue(const nlohmann::json& value, std::string file, std::string path = "$")
      : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

  const nlohmann::json& raw() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  [[noreturn]] void fail(std::string_view what) const;

  bool is_null() const { return value_->is_null(); }
  // Objects: a required member, an optional one, and a check that no other keys are present.
  JsonValue at(std::string_view key) const;
  std::optional<JsonValue> find(std::string_view key) const;
  void only_keys(std::initializer_list<std::string_view> allowed) const;
  void only_keys(const std::vector<std::string>& allowed) const;
  // Arrays.
  std::size_t size() const;  // fails unless an array
  JsonValue operator[](std::size_t i) const;

  double number() const;        // finite
  double positive() const;      // finite, > 0
  double non_negative() const;  // finite, >= 0
  double probability() const;   // in [0, 1]
  std::uint64_t unsigned_integer() const;
  bool boolean() const;
  std::string string() const;
  std::string one_of(std::initializer_list<std::string_view> choices) const;
  std::string one_of(const std::vector<std::string>& choices) const;
  Vec2 point() const;                // [x, y], finite
  std::vector<Vec2> points() const;  // [[x, y], ...]

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

}  // namespace covsim
