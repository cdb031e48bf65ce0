#pragma once
// Parameters declared beside the components that take them (planners, coverage laws, loss
// and delay models, densities), as OMPL's ParamSet and ns-3's attributes do: each has a name,
// a kind, a unit, bounds, a default (a constant, or a rule said in words when it depends on
// the environment) and a one-line description. The scenario loader reads a component's JSON
// section through its schema, `covsim list` prints the schema, and factories read the
// validated values from Params.
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "core/vec2.hpp"

namespace covsim {

class Environment;

enum class ParamKind {
  number,   // a finite real number
  integer,  // a whole number >= 0
  boolean,
  choice,   // one of a list of words
  text,     // free text (a file name)
  point,    // [x, y]
  extent,   // [[x_min, y_min], [x_max, y_max]]
  objects,  // a list of objects, each with the fields of a nested schema
};
std::string_view to_string(ParamKind k);

class Params;
using ParamObjects = std::vector<Params>;
// std::monostate is null (for a parameter declared nullable).
using ParamValue =
    std::variant<std::monostate, double, std::uint64_t, bool, std::string, Vec2, Box, ParamObjects>;

struct ParamSpec {
  std::string name;
  ParamKind kind = ParamKind::number;
  std::string unit;  // "m", "s", "m/s"; empty for a pure number
  std::string description;
  std::optional<double> min, max;  // numbers and integers
  bool min_exclusive = false, max_exclusive = false;
  std::vector<std::string> choices;
  // What an error calls the value when it is out of bounds, before the bounds it states
  // ("a fraction of the robots' spacing" > 0 and <= 1); empty: the kind ("a number").
  std::string expected;
  std::optional<ParamValue> default_value;  // a constant default
  std::string default_rule;                 // a default that depends on the run, in words
  // The rule's value for an environment (what `covsim describe` shows and factories use).
  std::function<ParamValue(const Environment&)> derive;
  bool nullable = false;          // null is a value (the description says what)
  std::vector<ParamSpec> fields;  // objects: the fields of each element

  bool required() const { return !default_value && default_rule.empty(); }

  static ParamSpec number(std::string name, std::string unit, std::string description);
  static ParamSpec integer(std::string name, std::string unit, std::string description);
  static ParamSpec boolean(std::string name, std::string description);
  static ParamSpec choice(std::string name, std::vector<std::string> choices,
                          std::string description);
  static ParamSpec text(std::string name, std::string description);
  static ParamSpec point(std::string name, std::string unit, std::string description);
  static ParamSpec extent(std::string name, std::string unit, std::string description);
  static ParamSpec objects(std::string name, std::vector<ParamSpec> fields,
                           std::string description);
  ParamSpec& at_least(double v);
  ParamSpec& greater_than(double v);
  ParamSpec& at_most(double v);
  ParamSpec& below(double v);
  // The usual bounds: > 0, >= 0, and [0, 1].
  ParamSpec& positive();
  ParamSpec& non_negative();
  ParamSpec& probability();
  ParamSpec& worded(std::string expected_text);
  ParamSpec& defaults_to(ParamValue v);
  ParamSpec& derived(std::string rule,
                     std::function<ParamValue(const Environment&)> value = nullptr);
  ParamSpec& or_null();
};

using ParamSchema = std::vector<ParamSpec>;

const ParamSpec* find_param(const ParamSchema& schema, std::string_view name);
// Whether a value fits its spec: empty if it does, else what was expected ("expected a
// number > 0, found -1").
std::string check_param(const ParamSpec& spec, const ParamValue& value);
// "0.1", "[1, 2]", "null", "true": a value as the JSON it came from would show it.
std::string to_text(const ParamValue& v);

// A factory's complaint about one of its parameters, beyond what the schema checks (a file
// that cannot be read, max below min): the loader names the parameter's JSON path.
class ParamError : public std::runtime_error {
 public:
  ParamError(std::string param, const std::string& what)
      : std::runtime_error(what), param_(std::move(param)) {}
  const std::string& param() const { return param_; }

 private:
  std::string param_;
};

// Validated parameter values, by name. Getters throw ParamError for a parameter that is not
// set (or set to null, for the non-optional ones).
class Params {
 public:
  void set(std::string name, ParamValue v);
  bool has(std::string_view name) const;  // set and not null
  bool is_null(std::string_view name) const;
  double number(std::string_view name) const;
  std::optional<double> maybe_number(std::string_view name) const;
  std::uint64_t integer(std::string_view name) const;
  std::optional<std::uint64_t> maybe_integer(std::string_view name) const;
  bool boolean(std::string_view name) const;
  const std::string& text(std::string_view name) const;
  Vec2 point(std::string_view name) const;
  Box extent(std::string_view name) const;
  const ParamObjects& objects(std::string_view name) const;
  const std::vector<std::pair<std::string, ParamValue>>& values() const { return values_; }
  friend bool operator==(const Params&, const Params&);

 private:
  const ParamValue* find(std::string_view name) const;
  template <class T>
  const T& get(std::string_view name) const;
  std::vector<std::pair<std::string, ParamValue>> values_;
};

// The schema's constant defaults filled in for the parameters not set. Throws ParamError for
// a required parameter that is missing.
Params with_defaults(const ParamSchema& schema, Params p);
// The derived defaults computed for an environment, for the parameters not set.
Params with_derived(const ParamSchema& schema, Params p, const Environment& env);

// A schema as `covsim list` prints it: one line per parameter (name, kind, default, unit,
// bounds, description), nested fields indented.
std::string describe(const ParamSchema& schema, const std::string& indent = "    ");
// A schema as a Markdown table (key, kind, unit, default, bounds, description), for the
// documentation's generated tables.
std::string markdown_table(const ParamSchema& schema);
// A parameter's default in words: a constant as JSON, a rule, "null", or "required".
std::string default_text(const ParamSpec& spec);
// Its bounds in words: "> 0", ">= 0 and <= 1"; empty when unbounded.
std::string bounds_text(const ParamSpec& spec);

}  // namespace covsim
