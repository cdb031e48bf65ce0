#include "scenarios/json_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scenarios/input_file.hpp"

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

namespace {
// Where the parser is: a frame per open object (its keys so far, its current key) or array
// (its current index), so that an error can name the JSON path.
struct Frame {
  bool object;
  std::vector<std::string> keys;
  std::ptrdiff_t index = -1;
};

// The path of the value being read, or with `container` of the innermost open object or
// array itself.
std::string path_of(const std::vector<Frame>& frames, bool container = false) {
  std::string path = "$";
  for (std::size_t k = 0; k + (container ? 1 : 0) < frames.size(); ++k) {
    const Frame& f = frames[k];
    if (f.object && !f.keys.empty()) path += "." + f.keys.back();
    if (!f.object && f.index >= 0) path += fmt::format("[{}]", f.index);
  }
  if (path.size() > 80) path = path.substr(0, 60) + "...";  // a deep nest's path
  return path;
}

// Line and column of a byte offset (1-based).
std::pair<std::size_t, std::size_t> place(const std::string& text, std::size_t byte) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}
}  // namespace

nlohmann::json parse_json(const std::string& text, const std::string& source) {
  std::vector<Frame> frames;
  const auto element = [&] {  // a value starts: the next element of an enclosing array
    if (!frames.empty() && !frames.back().object) ++frames.back().index;
  };
  using Event = nlohmann::json::parse_event_t;
  const nlohmann::json::parser_callback_t check = [&](int depth, Event event,
                                                      nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        element();
        if (static_cast<std::size_t>(depth) >= kMaxJsonDepth)
          throw ScenarioError(source, path_of(frames),
                              fmt::format("JSON nested deeper than {} levels", kMaxJsonDepth));
        frames.push_back({event == Event::object_start, {}, -1});
        break;
      case Event::object_end:
      case Event::array_end:
        if (!frames.empty()) frames.pop_back();
        break;
      case Event::key: {
        Frame& f = frames.back();
        const std::string key = parsed.get<std::string>();
        if (std::find(f.keys.begin(), f.keys.end(), key) != f.keys.end()) {
          throw ScenarioError(source, path_of(frames, true),
                              fmt::format("duplicate key \"{}\" (each key once)", key));
        }
        f.keys.push_back(key);
        break;
      }
      case Event::value:
        element();
        break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, check);
  } catch (const nlohmann::json::parse_error& e) {
    const auto [line, col] = place(text, e.byte > 0 ? e.byte - 1 : 0);
    std::string what = e.what();
    if (const auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
    throw ScenarioError(fmt::format("{}:{}:{}: malformed JSON: {}", source, line, col, what));
  } catch (const nlohmann::json::out_of_range& e) {
    // A number beyond a double's range (1e999): name it and where it first appears.
    std::string what = e.what(), token;
    if (const auto a = what.find('\''), b = what.rfind('\''); a != std::string::npos && b > a)
      token = what.substr(a + 1, b - a - 1);
    const std::size_t at = token.empty() ? std::string::npos : text.find(token);
    if (at == std::string::npos)
      throw ScenarioError(fmt::format("{}: a number is out of a double's range", source));
    const auto [line, col] = place(text, at);
    throw ScenarioError(
        fmt::format("{}:{}:{}: the number {} is out of a double's range (about ±1.8e308)", source,
                    line, col, token));
  }
}

nlohmann::json read_json_file(const std::filesystem::path& file) {
  return parse_json(read_text_file(file, "JSON"), file.string());
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
  // 1e9 is a whole number written as JSON writes large ones.
  if (value_->is_number_float()) {
    const double v = value_->get<double>();
    if (v >= 0.0 && v < 18446744073709551616.0 && std::floor(v) == v)
      return static_cast<std::uint64_t>(v);
  }
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
