#include "sim/provenance.hpp"

#include <fmt/format.h>

#include "core/build_info.hpp"

namespace covsim {

namespace {
constexpr const char* kKeys[] = {"version", "commit", "dirty", "compiler", "build_type", "flags"};

std::string text(const nlohmann::json& j, const char* key) {
  if (!j.contains(key)) return "unknown";
  const nlohmann::json& v = j.at(key);
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}
}  // namespace

nlohmann::ordered_json this_build() {
  const BuildInfo& b = build_info();
  return nlohmann::ordered_json{{"version", b.version},       {"commit", b.commit},
                                {"dirty", b.dirty},           {"compiler", b.compiler},
                                {"build_type", b.build_type}, {"flags", b.flags}};
}

std::string describe_build(const nlohmann::json& p) {
  const bool dirty = p.contains("dirty") && p.at("dirty").is_boolean() && p.at("dirty").get<bool>();
  return fmt::format("covsim {} (commit {}{}; {}, {}; {})", text(p, "version"),
                     text(p, "commit").substr(0, 12), dirty ? ", dirty" : "", text(p, "compiler"),
                     text(p, "build_type"), text(p, "flags"));
}

std::vector<std::string> build_differences(const nlohmann::json& a, const nlohmann::json& b,
                                           std::string_view pattern) {
  std::vector<std::string> out;
  for (const char* key : kKeys) {
    const std::string x = text(a, key), y = text(b, key);
    if (x != y) out.push_back(fmt::format(fmt::runtime(pattern), key, x, y));
  }
  return out;
}

std::vector<std::string> build_differences(const nlohmann::json& recorded) {
  return build_differences(recorded, this_build(), "{}: {} then, {} now");
}

void add_provenance(TraceHeader& header) {
  const nlohmann::ordered_json build = this_build();
  for (const auto& [key, value] : build.items())
    header.entries.emplace_back("build." + key,
                                value.is_string() ? value.get<std::string>() : value.dump());
}

nlohmann::json provenance_of(const TraceHeader& header) {
  nlohmann::json p = nlohmann::json::object();
  for (const auto& [key, value] : header.entries) {
    if (key.rfind("build.", 0) != 0) continue;
    const std::string name = key.substr(6);
    p[name] = name == "dirty" ? nlohmann::json(value == "true") : nlohmann::json(value);
  }
  return p;
}

}  // namespace covsim
