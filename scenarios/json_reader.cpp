#include "scenarios/json_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace covsim {

namespace {
std::string kind(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    default:
      return "a number";
  }
}
}  // namespace

nlohmann::json read_json_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ScenarioError(file.string() + ": cannot open file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // Turn the byte offset into a line and column.
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    std::string what = e.what();
    if (const auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
    throw ScenarioError(
        fmt::format("{}:{}:{}: malformed JSON: {}", file.string(), line, col, what));
  }
}

void JsonValue::fail(std::string_view what) const {
  throw ScenarioError(file_, path_, std::string(what));
}

JsonValue JsonValue::at(std::string_view key) const {
  auto v = find(key);
  if (!v) fail(fmt::format("missing required key \"{}\"", key));
  return *v;
}

std::optional<JsonValue> JsonValue::find(std::string_view key) const {
  if (!value_->is_object()) fail("expected an object, found " + kind(*value_));
  const auto it = value_->find(std::string(key));
  if (it == value_->end()) return std::nullopt;
  return JsonValue(*it, file_, fmt::format("{}.{}", path_, key));
}

void JsonValue::only_keys(std::initializer_list<std::string_view> allowed) const {
  only_keys(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void JsonValue::only_keys(const std::vector<std::string>& allowed) const {
  if (!value_->is_object()) fail("expected an object, found " + kind(*value_));
  for (const auto& [key, v] : value_->items()) {
    bool known = false;
    for (const std::string& a : allowed)
      known = known || a == key;
    if (!known) {
      std::string list;
      for (const std::string& a : allowed)
        list += (list.empty() ? "" : ", ") + a;
      throw ScenarioError(file_, fmt::format("{}.{}", path_, key),
                          fmt::format("unknown key \"{}\" (expected one of: {})", key, list));
    }
  }
}

std::size_t JsonValue::size() const {
  if (!value_->is_array()) fail("expected an array, found " + kind(*value_));
  return value_->size();
}

JsonValue JsonValue::operator[](std::size_t i) const {
  size();
  return JsonValue((*value_)[i], file_, fmt::format("{}[{}]", path_, i));
}

double JsonValue::number() const {
  if (!value_->is_number()) fail("expected a number, found " + kind(*value_));
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("expected a finite number");
  return v;
}

double JsonValue::positive() const {
  const double v = number();
  if (!(v > 0.0)) fail(fmt::format("expected a positive number, found {}", v));
  return v;
}

double JsonValue::non_negative() const {
  const double v = number();
  if (v < 0.0) fail(fmt::format("expected a non-negative number, found {}", v));
  return v;
}

double JsonValue::probability() const {
  const double v = number();
  if (v < 0.0 || v > 1.0) fail(fmt::format("expected a probability in [0, 1], found {}", v));
  return v;
}

std::uint64_t JsonValue::unsigned_integer() const {
  if (value_->is_number_unsigned()) return value_->get<std::uint64_t>();
  if (value_->is_number_integer() && value_->get<std::int64_t>() >= 0)
    return value_->get<std::uint64_t>();
  fail("expected a non-negative integer, found " +
       (value_->is_number() ? value_->dump() : kind(*value_)));
}

bool JsonValue::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false, found " + kind(*value_));
  return value_->get<bool>();
}

std::string JsonValue::string() const {
  if (!value_->is_string()) fail("expected a string, found " + kind(*value_));
  return value_->get<std::string>();
}

std::string JsonValue::one_of(std::initializer_list<std::string_view> choices) const {
  return one_of(std::vector<std::string>(choices.begin(), choices.end()));
}

std::string JsonValue::one_of(const std::vector<std::string>& choices) const {
  const std::string s = string();
  std::string list;
  for (const std::string& c : choices) {
    if (c == s) return s;
    list += (list.empty() ? "\"" : ", \"") + c + "\"";
  }
  fail(fmt::format("expected one of {}, found \"{}\"", list, s));
}

Vec2 JsonValue::point() const {
  if (!value_->is_array() || value_->size() != 2)
    fail("expected a point [x, y], found " + value_->dump());
  return Vec2{(*this)[0].number(), (*this)[1].number()};
}

std::vector<Vec2> JsonValue::points() const {
  std::vector<Vec2> out;
  const std::size_t n = size();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    out.push_back((*this)[i].point());
  return out;
}

}  // namespace covsim
