#include "scenarios/yaml_reader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "scenarios/json_reader.hpp"

namespace covsim {

namespace {

constexpr std::string_view kCoreTag = "tag:yaml.org,2002:";  // what !! stands for
constexpr const char* kNotUtf8 = "a scalar that is not UTF-8 (the file is read as UTF-8)";

TextPlace place_of_mark(const YAML::Mark& m) {
  if (m.is_null()) return {};
  return {static_cast<std::size_t>(m.line) + 1, static_cast<std::size_t>(m.column) + 1};
}

// The core schema's plain scalars that are not strings (YAML 1.2, 10.3.2).
bool is_yaml_null(std::string_view s) {
  return s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL";
}

std::optional<bool> yaml_bool(std::string_view s) {
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  return std::nullopt;
}

bool only_chars(std::string_view s, std::string_view allowed) {
  return !s.empty() && s.find_first_not_of(allowed) == std::string_view::npos;
}

constexpr std::string_view kDigits = "0123456789";

std::string_view unsigned_part(std::string_view s) {
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
  return s;
}

// [-+]?[0-9]+
bool is_yaml_decimal(std::string_view s) {
  return only_chars(unsigned_part(s), kDigits);
}

// [-+]? ( \. [0-9]+ | [0-9]+ ( \. [0-9]* )? ) ( [eE] [-+]? [0-9]+ )?
bool is_yaml_float(std::string_view s) {
  s = unsigned_part(s);
  const auto digits = [&s] {
    const std::size_t n = std::min(s.find_first_not_of(kDigits), s.size());
    s.remove_prefix(n);
    return n;
  };
  std::size_t mantissa = digits();
  if (!s.empty() && s.front() == '.') {
    s.remove_prefix(1);
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (!s.empty() && (s.front() == 'e' || s.front() == 'E')) {
    s = unsigned_part(s.substr(1));
    if (digits() == 0) return false;
  }
  return s.empty();
}

bool is_yaml_infinity_or_nan(std::string_view s) {
  const std::string_view u = unsigned_part(s);
  return u == ".inf" || u == ".Inf" || u == ".INF" || s == ".nan" || s == ".NaN" || s == ".NAN";
}

// Whether text is well-formed UTF-8 (Unicode's table 3-7: no overlong forms, no surrogates,
// nothing beyond U+10FFFF), as the JSON parser demands of every string; yaml-cpp passes any
// bytes through.
bool is_utf8(std::string_view s) {
  const auto at = [&s](std::size_t k) {
    return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u;
  };
  for (std::size_t i = 0; i < s.size();) {
    const unsigned lead = at(i);
    if (lead < 0x80) {
      ++i;
      continue;
    }
    // The length of the sequence the lead byte starts, and the range of its second byte.
    std::size_t n = 0;
    unsigned low = 0x80, high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
      n = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      n = 3;
      if (lead == 0xE0) low = 0xA0;   // overlong
      if (lead == 0xED) high = 0x9F;  // surrogates
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      n = 4;
      if (lead == 0xF0) low = 0x90;   // overlong
      if (lead == 0xF4) high = 0x8F;  // beyond U+10FFFF
    } else {
      return false;
    }
    if (at(i + 1) < low || at(i + 1) > high) return false;
    for (std::size_t k = 2; k < n; ++k) {
      if ((at(i + k) & 0xC0u) != 0x80u) return false;
    }
    i += n;
  }
  return true;
}

// Whether decimal text that a double cannot hold is too large rather than too small: its
// first significant digit stands left of the decimal point once the exponent is applied.
bool beyond_largest(std::string_view s) {
  s = unsigned_part(s);
  const std::size_t e = s.find_first_of("eE");
  long long exponent = 0;
  if (e != std::string_view::npos) {
    std::string_view digits = s.substr(e + 1);
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
    if (r.ec == std::errc::result_out_of_range) return digits.front() != '-';
    s = s.substr(0, e);
  }
  const std::size_t dot = std::min(s.find('.'), s.size());
  const std::string_view whole = s.substr(0, dot);
  if (const std::size_t lead = whole.find_first_not_of('0'); lead != std::string_view::npos)
    return exponent > -static_cast<long long>(whole.size() - lead);
  const std::string_view fraction = s.substr(std::min(dot + 1, s.size()));
  const std::size_t lead = fraction.find_first_not_of('0');
  return lead != std::string_view::npos && exponent > static_cast<long long>(lead);
}

// Decimal text as a correctly rounded double, independent of the locale, as parse_json reads
// it: a number too small for a double is 0 of its sign (strtod's answer), one too large is
// nothing.
std::optional<double> decimal_double(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);  // from_chars takes '-' only
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec == std::errc()) return v;  // the whole text: the caller matched its pattern
  if (beyond_largest(s)) return std::nullopt;
  return s.front() == '-' ? -0.0 : 0.0;
}

// Builds the JSON value from yaml-cpp's parse events, one frame per open sequence or mapping,
// and records where each value starts under its JSON path.
class JsonBuilder final : public YAML::EventHandler {
 public:
  explicit JsonBuilder(InputFile& out) : out_(out) {}

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (documents_++ > 0)
      throw ScenarioError(
          fmt::format("{}: a second YAML document (a file holds one)", at(place_of_mark(mark))));
  }
  void OnDocumentEnd() override {}

  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override {
    if (key_expected()) fail(mark, stack_.back().path, "expected a key, found null");
    begin_value(mark, false);
    add(nullptr);
  }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                const std::string& text) override {
    if (key_expected()) return key(mark, tag, text);
    const std::string path = begin_value(mark, false);
    add(scalar(mark, path, tag, text));
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                       YAML::EmitterStyle::value style) override {
    open(mark, tag, style, nlohmann::json::array());
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                  YAML::EmitterStyle::value style) override {
    open(mark, tag, style, nlohmann::json::object());
  }
  void OnMapEnd() override { close(); }
  // Refused: a value written once and used in several places has no single line to name in
  // an error, and JSON cannot say it either.
  void OnAnchor(const YAML::Mark& mark, const std::string& name) override {
    const std::string what = "anchors (&" + name + ") and aliases are not read";
    fail(mark, next_path(), what + ": write the value out where it is used");
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override {
    fail(mark, next_path(), "aliases (*name) are not read: write the value out where it is used");
  }

 private:
  struct Open {
    nlohmann::json value;            // the array or object being filled
    std::string path;                // its JSON path
    std::optional<std::string> key;  // an object's key whose value comes next
    TextPlace key_place;
  };

  std::string at(TextPlace p) const {
    return p.known() ? fmt::format("{}:{}:{}", out_.source, p.line, p.column) : out_.source;
  }
  [[noreturn]] void fail(const YAML::Mark& mark, std::string path, const std::string& what) const {
    if (path.size() > 80) path = path.substr(0, 60) + "...";  // a deep nest's path
    throw ScenarioError(out_.source, place_of_mark(mark), path, what);
  }

  bool key_expected() const {
    return !stack_.empty() && stack_.back().value.is_object() && !stack_.back().key;
  }
  // The path of the value that starts next.
  std::string next_path() const {
    if (stack_.empty()) return "$";
    const Open& o = stack_.back();
    if (o.value.is_object()) return o.key ? o.path + "." + *o.key : o.path;
    return fmt::format("{}[{}]", o.path, o.value.size());
  }
  // Records where the next value starts: a block collection under a key starts on the lines
  // below it, so its key's place is the one to name.
  std::string begin_value(const YAML::Mark& mark, bool block) {
    std::string path = next_path();
    const bool under_key = !stack_.empty() && stack_.back().value.is_object();
    out_.places.emplace(path, block && under_key ? stack_.back().key_place : place_of_mark(mark));
    return path;
  }
  void add(nlohmann::json v) {
    if (stack_.empty()) {
      out_.json = std::move(v);
      return;
    }
    Open& o = stack_.back();
    if (o.value.is_object()) {
      o.value.emplace(std::move(*o.key), std::move(v));
      o.key.reset();
    } else {
      o.value.push_back(std::move(v));
    }
  }

  void key(const YAML::Mark& mark, const std::string& tag, const std::string& text) {
    Open& o = stack_.back();
    if (!is_utf8(text)) fail(mark, o.path, kNotUtf8);
    if (tag != "?" && tag != "!" && tag != std::string(kCoreTag) + "str")
      fail(mark, o.path, fmt::format("a key is a string; found the tag {}", shown(tag)));
    if (tag == "?" && text == "<<")
      fail(mark, o.path, "merge keys (<<) are not read: write the keys out");
    if (o.value.contains(text))
      fail(mark, o.path, fmt::format("duplicate key \"{}\" (each key once)", text));
    o.key = text;
    o.key_place = place_of_mark(mark);
  }

  void open(const YAML::Mark& mark, const std::string& tag, YAML::EmitterStyle::value style,
            nlohmann::json empty) {
    const char* kind = empty.is_object() ? "mapping" : "sequence";
    if (key_expected())
      fail(mark, stack_.back().path, fmt::format("a key is a string, not a {}", kind));
    const std::string path = begin_value(mark, style == YAML::EmitterStyle::Block);
    if (tag != "?" && tag != "!" &&
        tag != std::string(kCoreTag) + (empty.is_object() ? "map" : "seq"))
      fail(mark, path, fmt::format("the tag {} is not read on a {}", shown(tag), kind));
    if (stack_.size() >= kMaxJsonDepth)
      fail(mark, path, fmt::format("YAML nested deeper than {} levels", kMaxJsonDepth));
    stack_.push_back({std::move(empty), path, std::nullopt, {}});
  }
  void close() {
    nlohmann::json v = std::move(stack_.back().value);
    stack_.pop_back();
    add(std::move(v));
  }

  static std::string shown(const std::string& tag) {
    if (tag.rfind(kCoreTag, 0) == 0) return "!!" + tag.substr(kCoreTag.size());
    return tag;
  }

  // A scalar by its tag: "?" (plain, none given) by the core schema, "!" (quoted or block)
  // a string, or one of the core schema's tags.
  nlohmann::json scalar(const YAML::Mark& mark, const std::string& path, const std::string& tag,
                        const std::string& text) const {
    if (!is_utf8(text)) fail(mark, path, kNotUtf8);
    if (tag == "?") return plain(mark, path, text);
    if (tag == "!") return text;
    const std::string name = tag.rfind(kCoreTag, 0) == 0 ? tag.substr(kCoreTag.size()) : "";
    if (name == "str") return text;
    if (name == "null" && is_yaml_null(text)) return nullptr;
    if (name == "bool" && yaml_bool(text)) return *yaml_bool(text);
    if (name == "int" && is_integer(text)) return integer(mark, path, text);
    if (name == "float" && (is_yaml_float(text) || is_yaml_decimal(text)))
      return number(mark, path, text);
    if (name == "float" && is_yaml_infinity_or_nan(text)) not_finite(mark, path, text);
    if (name == "null" || name == "bool" || name == "int" || name == "float")
      fail(mark, path, fmt::format("\"{}\" is not a {}", text, shown(tag)));
    fail(mark, path,
         fmt::format("the tag {} is not read (only the core schema's !!str, !!int, !!float, "
                     "!!bool, !!null, !!seq and !!map)",
                     shown(tag)));
  }
  nlohmann::json plain(const YAML::Mark& mark, const std::string& path,
                       const std::string& text) const {
    if (is_yaml_null(text)) return nullptr;
    if (const auto b = yaml_bool(text)) return *b;
    if (is_integer(text)) return integer(mark, path, text);
    if (is_yaml_float(text)) return number(mark, path, text);
    if (is_yaml_infinity_or_nan(text)) not_finite(mark, path, text);
    return text;
  }

  static bool is_integer(std::string_view s) {
    return is_yaml_decimal(s) || (s.substr(0, 2) == "0o" && only_chars(s.substr(2), "01234567")) ||
           (s.substr(0, 2) == "0x" && only_chars(s.substr(2), "0123456789abcdefABCDEF"));
  }
  // As parse_json: unsigned when not negative, signed when negative, and a double when 64
  // bits cannot hold it.
  nlohmann::json integer(const YAML::Mark& mark, const std::string& path,
                         std::string_view s) const {
    if (s.substr(0, 2) == "0o" || s.substr(0, 2) == "0x") {
      std::uint64_t v = 0;
      const std::string_view digits = s.substr(2);
      const auto r =
          std::from_chars(digits.data(), digits.data() + digits.size(), v, s[1] == 'o' ? 8 : 16);
      if (r.ec != std::errc()) fail(mark, path, fmt::format("{} is beyond 64 bits", s));
      return v;
    }
    if (s.front() == '-') {
      std::int64_t v = 0;
      if (std::from_chars(s.data(), s.data() + s.size(), v).ec == std::errc()) return v;
    } else {
      const std::string_view u = unsigned_part(s);
      std::uint64_t v = 0;
      if (std::from_chars(u.data(), u.data() + u.size(), v).ec == std::errc()) return v;
    }
    return number(mark, path, s);
  }
  nlohmann::json number(const YAML::Mark& mark, const std::string& path, std::string_view s) const {
    const std::optional<double> v = decimal_double(s);
    if (!v)
      fail(mark, path, fmt::format("the number {} is out of a double's range (about ±1.8e308)", s));
    return *v;
  }
  [[noreturn]] void not_finite(const YAML::Mark& mark, const std::string& path,
                               const std::string& text) const {
    fail(mark, path,
         fmt::format("expected a finite number, found {} (JSON has no infinity or NaN either)",
                     text));
  }

  InputFile& out_;
  std::vector<Open> stack_;
  int documents_ = 0;
};

}  // namespace

InputFile parse_yaml(const std::string& text, const std::string& source) {
  InputFile out{nullptr, source, {}};
  std::istringstream in(text);
  try {
    YAML::Parser parser(in);
    JsonBuilder builder(out);
    if (!parser.HandleNextDocument(builder))
      throw ScenarioError(source + ":1:1: malformed YAML: no document (the file is empty)");
    parser.HandleNextDocument(builder);  // a second document is refused as it starts
  } catch (const YAML::Exception& e) {
    const TextPlace p = place_of_mark(e.mark);
    throw ScenarioError(
        p.known() ? fmt::format("{}:{}:{}: malformed YAML: {}", source, p.line, p.column, e.msg)
                  : fmt::format("{}: malformed YAML: {}", source, e.msg));
  }
  return out;
}

}  // namespace covsim
