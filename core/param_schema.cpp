#include "core/param_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace covsim {

std::string_view to_string(ParamKind k) {
  switch (k) {
    case ParamKind::number:
      return "number";
    case ParamKind::integer:
      return "integer";
    case ParamKind::boolean:
      return "boolean";
    case ParamKind::choice:
      return "choice";
    case ParamKind::text:
      return "text";
    case ParamKind::point:
      return "point";
    case ParamKind::extent:
      return "extent";
    case ParamKind::objects:
      return "objects";
  }
  return "unknown";
}

namespace {
ParamSpec make(std::string name, ParamKind kind, std::string unit, std::string description) {
  ParamSpec s;
  s.name = std::move(name);
  s.kind = kind;
  s.unit = std::move(unit);
  s.description = std::move(description);
  return s;
}

std::string number_text(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt::format("{}", v);
}

std::string kind_text(const ParamSpec& s) {
  switch (s.kind) {
    case ParamKind::number:
      return "a number";
    case ParamKind::integer:
      return "a whole number";
    case ParamKind::boolean:
      return "true or false";
    case ParamKind::choice: {
      std::string out = "one of";
      for (std::size_t i = 0; i < s.choices.size(); ++i)
        out += fmt::format("{} \"{}\"", i == 0 ? "" : ",", s.choices[i]);
      return out;
    }
    case ParamKind::text:
      return "a string";
    case ParamKind::point:
      return "a point [x, y]";
    case ParamKind::extent:
      return "[[x_min, y_min], [x_max, y_max]]";
    case ParamKind::objects:
      return "a list of objects";
  }
  return "a value";
}
}  // namespace

std::string bounds_text(const ParamSpec& s) {
  std::string out;
  if (s.min) out += fmt::format("{} {}", s.min_exclusive ? ">" : ">=", number_text(*s.min));
  if (s.max) {
    if (!out.empty()) out += " and ";
    out += fmt::format("{} {}", s.max_exclusive ? "<" : "<=", number_text(*s.max));
  }
  return out;
}

ParamSpec ParamSpec::number(std::string name, std::string unit, std::string description) {
  return make(std::move(name), ParamKind::number, std::move(unit), std::move(description));
}
ParamSpec ParamSpec::integer(std::string name, std::string unit, std::string description) {
  return make(std::move(name), ParamKind::integer, std::move(unit), std::move(description));
}
ParamSpec ParamSpec::boolean(std::string name, std::string description) {
  return make(std::move(name), ParamKind::boolean, "", std::move(description));
}
ParamSpec ParamSpec::choice(std::string name, std::vector<std::string> choices,
                            std::string description) {
  ParamSpec s = make(std::move(name), ParamKind::choice, "", std::move(description));
  s.choices = std::move(choices);
  return s;
}
ParamSpec ParamSpec::text(std::string name, std::string description) {
  return make(std::move(name), ParamKind::text, "", std::move(description));
}
ParamSpec ParamSpec::point(std::string name, std::string unit, std::string description) {
  return make(std::move(name), ParamKind::point, std::move(unit), std::move(description));
}
ParamSpec ParamSpec::extent(std::string name, std::string unit, std::string description) {
  return make(std::move(name), ParamKind::extent, std::move(unit), std::move(description));
}
ParamSpec ParamSpec::objects(std::string name, std::vector<ParamSpec> fields,
                             std::string description) {
  ParamSpec s = make(std::move(name), ParamKind::objects, "", std::move(description));
  s.fields = std::move(fields);
  return s;
}
ParamSpec& ParamSpec::at_least(double v) {
  min = v;
  min_exclusive = false;
  return *this;
}
ParamSpec& ParamSpec::greater_than(double v) {
  min = v;
  min_exclusive = true;
  return *this;
}
ParamSpec& ParamSpec::at_most(double v) {
  max = v;
  max_exclusive = false;
  return *this;
}
ParamSpec& ParamSpec::below(double v) {
  max = v;
  max_exclusive = true;
  return *this;
}
ParamSpec& ParamSpec::positive() {
  return greater_than(0);
}
ParamSpec& ParamSpec::non_negative() {
  return at_least(0);
}
ParamSpec& ParamSpec::probability() {
  return at_least(0).at_most(1);
}
ParamSpec& ParamSpec::worded(std::string expected_text) {
  expected = std::move(expected_text);
  return *this;
}
ParamSpec& ParamSpec::defaults_to(ParamValue v) {
  default_value = std::move(v);
  return *this;
}
ParamSpec& ParamSpec::derived(std::string rule,
                              std::function<ParamValue(const Environment&)> value) {
  default_rule = std::move(rule);
  derive = std::move(value);
  return *this;
}
ParamSpec& ParamSpec::or_null() {
  nullable = true;
  return *this;
}

const ParamSpec* find_param(const ParamSchema& schema, std::string_view name) {
  for (const ParamSpec& s : schema) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

std::string to_text(const ParamValue& v) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, std::monostate>) return "null";
        if constexpr (std::is_same_v<T, double>) return number_text(x);
        if constexpr (std::is_same_v<T, std::uint64_t>) return fmt::format("{}", x);
        if constexpr (std::is_same_v<T, bool>) return x ? "true" : "false";
        if constexpr (std::is_same_v<T, std::string>) return "\"" + x + "\"";
        if constexpr (std::is_same_v<T, Vec2>) return fmt::format("[{}, {}]", x.x, x.y);
        if constexpr (std::is_same_v<T, Box>)
          return fmt::format("[[{}, {}], [{}, {}]]", x.lo.x, x.lo.y, x.hi.x, x.hi.y);
        if constexpr (std::is_same_v<T, ParamObjects>) return fmt::format("[{} objects]", x.size());
      },
      v);
}

std::string check_param(const ParamSpec& s, const ParamValue& v) {
  if (std::holds_alternative<std::monostate>(v)) {
    return s.nullable ? "" : fmt::format("expected {}, found null", kind_text(s));
  }
  const auto numeric = [&](double x) -> std::string {
    const bool ok = (!s.min || (s.min_exclusive ? x > *s.min : x >= *s.min)) &&
                    (!s.max || (s.max_exclusive ? x < *s.max : x <= *s.max));
    if (ok) return "";
    // Every bound, from the schema, with the unit: "expected a number > 0 and <= 1000 Hz".
    return fmt::format("expected {} {}{}, found {}", s.expected.empty() ? kind_text(s) : s.expected,
                       bounds_text(s), s.unit.empty() ? "" : " " + s.unit, number_text(x));
  };
  switch (s.kind) {
    case ParamKind::number:
      if (const auto* x = std::get_if<double>(&v)) {
        if (!std::isfinite(*x)) return fmt::format("expected a finite number, found {}", *x);
        return numeric(*x);
      }
      break;
    case ParamKind::integer:
      if (const auto* x = std::get_if<std::uint64_t>(&v)) return numeric(static_cast<double>(*x));
      break;
    case ParamKind::boolean:
      if (std::holds_alternative<bool>(v)) return "";
      break;
    case ParamKind::choice:
      if (const auto* x = std::get_if<std::string>(&v)) {
        if (std::find(s.choices.begin(), s.choices.end(), *x) != s.choices.end()) return "";
        return fmt::format("expected {}, found \"{}\"", kind_text(s), *x);
      }
      break;
    case ParamKind::text:
      if (std::holds_alternative<std::string>(v)) return "";
      break;
    case ParamKind::point:
      if (const auto* x = std::get_if<Vec2>(&v)) {
        return is_finite(*x) ? "" : "expected a point of finite coordinates";
      }
      break;
    case ParamKind::extent:
      if (const auto* x = std::get_if<Box>(&v)) {
        if (is_finite(x->lo) && is_finite(x->hi) && x->lo.x < x->hi.x && x->lo.y < x->hi.y)
          return "";
        return "expected [[x_min, y_min], [x_max, y_max]] with min < max";
      }
      break;
    case ParamKind::objects:
      if (std::holds_alternative<ParamObjects>(v)) return "";
      break;
  }
  return fmt::format("expected {}", kind_text(s));
}

void Params::set(std::string name, ParamValue v) {
  for (auto& [n, value] : values_) {
    if (n == name) {
      value = std::move(v);
      return;
    }
  }
  values_.emplace_back(std::move(name), std::move(v));
}

const ParamValue* Params::find(std::string_view name) const {
  for (const auto& [n, value] : values_) {
    if (n == name) return &value;
  }
  return nullptr;
}

bool Params::has(std::string_view name) const {
  const ParamValue* v = find(name);
  return v != nullptr && !std::holds_alternative<std::monostate>(*v);
}

bool Params::is_null(std::string_view name) const {
  const ParamValue* v = find(name);
  return v != nullptr && std::holds_alternative<std::monostate>(*v);
}

template <class T>
const T& Params::get(std::string_view name) const {
  const ParamValue* v = find(name);
  if (v == nullptr) throw ParamError(std::string(name), "missing required parameter");
  const T* x = std::get_if<T>(v);
  if (x == nullptr)
    throw ParamError(std::string(name), fmt::format("has the wrong kind: {}", to_text(*v)));
  return *x;
}

double Params::number(std::string_view name) const {
  return get<double>(name);
}
std::optional<double> Params::maybe_number(std::string_view name) const {
  return has(name) ? std::optional<double>(get<double>(name)) : std::nullopt;
}
std::uint64_t Params::integer(std::string_view name) const {
  return get<std::uint64_t>(name);
}
std::optional<std::uint64_t> Params::maybe_integer(std::string_view name) const {
  return has(name) ? std::optional<std::uint64_t>(get<std::uint64_t>(name)) : std::nullopt;
}
bool Params::boolean(std::string_view name) const {
  return get<bool>(name);
}
const std::string& Params::text(std::string_view name) const {
  return get<std::string>(name);
}
Vec2 Params::point(std::string_view name) const {
  return get<Vec2>(name);
}
Box Params::extent(std::string_view name) const {
  return get<Box>(name);
}
const ParamObjects& Params::objects(std::string_view name) const {
  return get<ParamObjects>(name);
}

bool operator==(const Params& a, const Params& b) {
  return a.values_ == b.values_;
}

Params with_defaults(const ParamSchema& schema, Params p) {
  for (const ParamSpec& s : schema) {
    if (p.has(s.name) || p.is_null(s.name)) continue;
    if (s.default_value) {
      p.set(s.name, *s.default_value);
    } else if (s.required()) {
      throw ParamError(s.name, fmt::format("missing required key \"{}\"", s.name));
    }
  }
  return p;
}

Params with_derived(const ParamSchema& schema, Params p, const Environment& env) {
  for (const ParamSpec& spec : schema) {
    if (spec.derive && !p.has(spec.name) && !p.is_null(spec.name))
      p.set(spec.name, spec.derive(env));
  }
  return p;
}

std::string default_text(const ParamSpec& s) {
  if (s.default_value) return to_text(*s.default_value);
  if (!s.default_rule.empty()) return s.default_rule;
  return s.nullable ? "null" : "required";
}

std::string describe(const ParamSchema& schema, const std::string& indent) {
  std::string out;
  for (const ParamSpec& s : schema) {
    const std::string text = default_text(s);
    const std::string def = text == "required" ? text : "default " + text;
    const std::string bounds = bounds_text(s);
    out +=
        fmt::format("{}{:<16} {:<8} {}{}{}{}  {}\n", indent, s.name, to_string(s.kind), def,
                    s.unit.empty() ? "" : " [" + s.unit + "]", bounds.empty() ? "" : ", " + bounds,
                    s.nullable ? ", null allowed" : "", s.description);
    if (s.kind == ParamKind::choice) {
      out += fmt::format("{}{:<16} {}\n", indent, "", kind_text(s));
    }
    if (!s.fields.empty()) out += describe(s.fields, indent + "    ");
  }
  return out;
}

std::string markdown_table(const ParamSchema& schema) {
  // A cell's text with the table's separator escaped.
  const auto cell = [](std::string text) {
    for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
      text.replace(at, 1, "\\|");
    return text;
  };
  std::string out =
      "| key | kind | unit | default | bounds | meaning |\n|---|---|---|---|---|---|\n";
  for (const ParamSpec& s : schema) {
    std::string kind(to_string(s.kind));
    if (s.kind == ParamKind::choice) kind = kind_text(s);
    std::string bounds = bounds_text(s);
    if (s.nullable) bounds += bounds.empty() ? "or null" : ", or null";
    const std::string def =
        s.default_value ? "`" + to_text(*s.default_value) + "`" : default_text(s);
    out += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", s.name, cell(kind), s.unit, cell(def),
                       cell(bounds), cell(s.description));
  }
  return out;
}

}  // namespace covsim
