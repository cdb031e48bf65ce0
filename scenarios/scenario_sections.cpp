#include "scenarios/scenario_sections.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace covsim {

namespace {
template <class Config>
ConfigKeys<Scenario> joined(ConfigKeys<Scenario> a, const ConfigKeys<Config>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<ScenarioSection> make_sections() {
  const auto coverage = [](const ConfigKeys<CoverageConfig>& keys) {
    return lift(keys, &Scenario::coverage);
  };
  std::vector<ScenarioSection> out;
  out.push_back({"robots",
                 "the robots: how they start and how fast they move",
                 joined(lift(robot_draw_keys(), &Scenario::draw), coverage(motion_keys())),
                 {"positions", "count", "start"}});
  out.push_back({"environment",
                 "Ω (outer ring and holes) and what the robots know of it",
                 coverage(environment_keys()),
                 {"outer", "holes"}});
  out.push_back({"mapping",
                 "how robots that do not know Ω (environment.known) map it",
                 coverage(mapping_keys()),
                 {}});
  out.push_back({"controller",
                 "the coverage law (covsim list laws); its key for every type",
                 coverage(projection_keys()),
                 {}});
  out.push_back({"sensor", "the range sensor", coverage(sensor_keys()), {}});
  out.push_back(
      {"loops", "how loop 1 (Lloyd) and loop 2 (motion) are scheduled", coverage(loop_keys()), {}});
  out.push_back({"convergence",
                 "when a run has converged, and when it gives up",
                 coverage(convergence_keys()),
                 {}});
  out.push_back({"metrics", "how often metrics are sampled", coverage(metrics_keys()), {}});
  out.push_back({"recording",
                 "how much of the trajectory a run folder keeps",
                 lift(recording_keys(), &Scenario::recording),
                 {}});
  out.push_back({"limits",
                 "how large a run may grow before it is refused",
                 lift(limit_keys(), &Scenario::limits),
                 {}});
  ScenarioSection network{"network",
                          "neighbour messages (null: the ideal network)",
                          lift(lift(network_keys(), &CoverageConfig::network), &Scenario::coverage),
                          {}};
  network.null_is_absent = true;
  out.push_back(std::move(network));
  return out;
}
}  // namespace

ParamSchema ScenarioSection::schema() const {
  ParamSchema out;
  for (const ConfigKey<Scenario>& k : keys)
    out.push_back(k.spec);
  return out;
}

const std::vector<ScenarioSection>& scenario_sections() {
  static const std::vector<ScenarioSection> sections = make_sections();
  return sections;
}

const ScenarioSection& scenario_section(std::string_view path) {
  for (const ScenarioSection& s : scenario_sections()) {
    if (s.path == path) return s;
  }
  throw std::invalid_argument(fmt::format("no scenario section \"{}\"", path));
}

const ParamSpec* find_section_key(std::string_view path) {
  for (const ScenarioSection& s : scenario_sections()) {
    if (path.size() <= s.path.size() || path.substr(0, s.path.size()) != s.path ||
        path[s.path.size()] != '.')
      continue;
    const std::string_view key = path.substr(s.path.size() + 1);
    for (const ConfigKey<Scenario>& k : s.keys) {
      if (k.spec.name == key) return &k.spec;
    }
  }
  return nullptr;
}

}  // namespace covsim
