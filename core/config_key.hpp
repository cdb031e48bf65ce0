#pragma once
// A key of a fixed scenario section (sensor, loops, network, ...): its parameter schema bound
// to the member of the config it fills, as ns-3's attributes carry their accessors. The
// loader sets the member through it, `covsim describe` reads the value back through it, and
// `covsim list` and the documentation print its schema: adding a key is one declaration
// beside the config and the code that uses the member.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/param_schema.hpp"
#include "core/sim_time.hpp"

namespace covsim {

class Environment;

// What a value written back may depend on besides the config: Ω and the number of robots
// (a tolerance derived from the robots' spacing).
struct RunShape {
  const Environment& environment;
  std::size_t robots;
};

template <class Config>
struct ConfigKey {
  // Its name is the key's path in the section, dotted for a key of a nested object
  // ("noise.sigma").
  ParamSpec spec;
  // Stores a value the spec accepts (null only for a nullable spec). Throws ParamError for a
  // rule the schema cannot state (a key that applies in one mode only).
  std::function<void(Config&, const ParamValue&)> set;
  // The value the run uses, defaults resolved; nullopt for a key `covsim describe` leaves out
  // (one that applies in another mode, or whose effect is written by other keys).
  std::function<std::optional<ParamValue>(const Config&, const RunShape&)> get;
};

template <class Config>
using ConfigKeys = std::vector<ConfigKey<Config>>;

// Periods a run resolves: from 0.1 ms (what a double's nanoseconds resolve over long runs)
// to 1e6 s.
inline constexpr double kMinPeriod = 1e-4;  // s
inline constexpr double kMaxPeriod = 1e6;   // s

// Seconds between events of a periodic clock, in [kMinPeriod, kMaxPeriod].
ParamSpec period_param(std::string name, std::string description);
// Seconds from the start, in [0, kMaxPeriod].
ParamSpec duration_param(std::string name, std::string description);

// A member's value as a parameter value and back: numbers, whole numbers, booleans, times
// (as seconds) and optional ones of these (unset is null).
namespace config_value {
inline ParamValue to(double v) {
  return v;
}
inline ParamValue to(bool v) {
  return v;
}
inline ParamValue to(std::uint64_t v) {
  return v;
}
inline ParamValue to(SimTime v) {
  return v.seconds();
}
template <class T>
ParamValue to(const std::optional<T>& v) {
  return v ? to(*v) : ParamValue(std::monostate{});
}
inline void from(const ParamValue& v, double& out) {
  out = std::get<double>(v);
}
inline void from(const ParamValue& v, bool& out) {
  out = std::get<bool>(v);
}
inline void from(const ParamValue& v, std::uint64_t& out) {
  out = std::get<std::uint64_t>(v);
}
inline void from(const ParamValue& v, SimTime& out) {
  out = SimTime::from_seconds(std::get<double>(v));
}
template <class T>
void from(const ParamValue& v, std::optional<T>& out) {
  if (std::holds_alternative<std::monostate>(v)) {
    out.reset();
    return;
  }
  T x{};
  from(v, x);
  out = x;
}
}  // namespace config_value

// A key stored in a member, reached through a path of members
// (&CoverageConfig::sensor, &SensorConfig::dropout); written back as stored.
template <class Config, class... Members>
ConfigKey<Config> member_key(ParamSpec spec, Members... path) {
  ConfigKey<Config> k;
  k.spec = std::move(spec);
  k.set = [path...](Config& c, const ParamValue& v) { config_value::from(v, (c.*....*path)); };
  k.get = [path...](const Config& c, const RunShape&) -> std::optional<ParamValue> {
    return config_value::to((c.*....*path));
  };
  return k;
}

// The same keys reached through a member of a larger config (Scenario::coverage).
template <class Outer, class Inner>
ConfigKeys<Outer> lift(const ConfigKeys<Inner>& keys, Inner Outer::*member) {
  ConfigKeys<Outer> out;
  for (const ConfigKey<Inner>& k : keys) {
    ConfigKey<Outer> o;
    o.spec = k.spec;
    o.set = [set = k.set, member](Outer& c, const ParamValue& v) { set(c.*member, v); };
    o.get = [get = k.get, member](const Outer& c, const RunShape& shape) {
      return get(c.*member, shape);
    };
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace covsim
