// The fixed sections of a scenario are declared once (scenario_sections.hpp): the loader
// reads every key through its schema, `covsim describe` writes it back, and
// docs/scenario-format.md's tables are the schemas'.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "scenarios/component_reader.hpp"
#include "scenarios/doc_tables.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_description.hpp"
#include "scenarios/scenario_error.hpp"
#include "scenarios/scenario_sections.hpp"

using namespace covsim;

namespace {
const char* kBase = R"({"environment": {"outer": [[0, 0], [4, 0], [4, 4], [0, 4]]},
                        "density": {"type": "uniform"}, "seed": 1})";

// The base scenario with `value` at a section's key ("noise.sigma": nested), and what
// a key needs beside it (robots need positions, loop1_period the periodic mode).
nlohmann::json with_key(const std::string& section, const std::string& key,
                        const nlohmann::json& value) {
  nlohmann::json j = nlohmann::json::parse(kBase);
  nlohmann::json& s = j[section];
  if (section == "robots") s["positions"] = {{0.5, 0.5}, {3.0, 3.0}};
  if (section == "loops" && key == "loop1_period") s["mode"] = "periodic";
  const auto dot = key.find('.');
  if (dot == std::string::npos)
    s[key] = value;
  else
    s[key.substr(0, dot)][key.substr(dot + 1)] = value;
  return j;
}

Scenario parse(const nlohmann::json& j) {
  return parse_scenario(j, "s.json", ".");
}

std::string error_of(const nlohmann::json& j) {
  try {
    parse(j);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

// A value inside the spec's bounds and unlike its default.
nlohmann::json other_value(const ParamSpec& spec) {
  switch (spec.kind) {
    case ParamKind::boolean:
      return !(spec.default_value && std::get<bool>(*spec.default_value));
    case ParamKind::choice:
      return spec.choices.back() == std::get<std::string>(*spec.default_value)
                 ? spec.choices.front()
                 : spec.choices.back();
    case ParamKind::integer:
      return 7;
    default: {
      const double* d = spec.default_value ? std::get_if<double>(&*spec.default_value) : nullptr;
      if (d != nullptr && *d > 0) return spec.max && 2 * *d > *spec.max ? *d / 2 : 2 * *d;
      const double lo = spec.min.value_or(0.0), hi = spec.max.value_or(lo + 2.0);
      return std::min(lo + 0.25 * (hi - lo), lo + 0.75);
    }
  }
}

std::string doc(const std::string& name) {
  std::ifstream in(std::string(COVSIM_SOURCE_DIR) + "/docs/" + name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("every key of every section has a schema: kind, default, description",
          "[scenario][sections]") {
  std::size_t keys = 0;
  for (const ScenarioSection& section : scenario_sections()) {
    INFO(section.path);
    CHECK_FALSE(section.description.empty());
    for (const ConfigKey<Scenario>& k : section.keys) {
      INFO(k.spec.name);
      CHECK_FALSE(k.spec.description.empty());
      CHECK(static_cast<bool>(k.set));
      CHECK(static_cast<bool>(k.get));
      ++keys;
    }
  }
  CHECK(keys >= 25);
  // The keys the sections hold today, by their dotted paths.
  for (const char* path :
       {"robots.max_speed", "robots.separation", "robots.jitter", "controller.projection",
        "sensor.range", "sensor.noise.sigma", "loops.loop1_period", "convergence.spacing_tolerance",
        "metrics.algebraic_connectivity_robots", "recording.compress", "limits.trajectory_rows",
        "network.acquire_timeout"})
    CHECK(find_section_key(path) != nullptr);
}

TEST_CASE("a section's defaults are its config's: a file without it runs with them",
          "[scenario][sections]") {
  nlohmann::json j = nlohmann::json::parse(kBase);
  j["robots"] = {{"positions", {{0.5, 0.5}, {3.0, 3.0}}}};
  j["loops"] = {{"mode", "periodic"}};  // loop1_period written back
  j["network"] = nlohmann::json::object();
  const Scenario s = parse(j);
  const RunShape shape{*s.environment, s.robot_positions.size()};
  for (const ScenarioSection& section : scenario_sections()) {
    for (const ConfigKey<Scenario>& k : section.keys) {
      INFO(section.path << "." << k.spec.name);
      if (!k.spec.default_value) continue;  // derived: checked by the round trip
      if (k.spec.name == "mode") continue;  // set above
      const std::optional<ParamValue> v = k.get(s, shape);
      if (!v) continue;  // not written back
      CHECK(*v == *k.spec.default_value);
    }
  }
  const nlohmann::json described = describe_scenario(s);
  CHECK(described["sensor"]["range"].is_null());
  CHECK(described["loops"]["loop1_period"] == 1.0);
  CHECK(described["network"]["acquire"] == 0.1);
  CHECK(described["network"]["acquire_timeout"] == Approx(1.0));
}

TEST_CASE("each key out of bounds, of the wrong kind or null is an error at its path",
          "[scenario][sections]") {
  for (const ScenarioSection& section : scenario_sections()) {
    for (const ConfigKey<Scenario>& k : section.keys) {
      const ParamSpec& spec = k.spec;
      const std::string path = "s.json: $." + section.path + "." + spec.name + ": expected ";
      INFO(path);
      if (spec.min) {
        const std::string e = error_of(with_key(section.path, spec.name, *spec.min - 1.0));
        CHECK_THAT(e, Catch::StartsWith(path));
        CHECK_THAT(e, Catch::Contains(spec.expected.empty() ? bounds_text(spec) : spec.expected));
      }
      if (spec.max) {
        const std::string e = error_of(with_key(section.path, spec.name, *spec.max * 2 + 1));
        CHECK_THAT(e, Catch::StartsWith(path));
      }
      const nlohmann::json wrong =
          spec.kind == ParamKind::boolean ? nlohmann::json(1) : nlohmann::json("x");
      if (spec.kind != ParamKind::choice && spec.kind != ParamKind::text)
        CHECK_THAT(error_of(with_key(section.path, spec.name, wrong)), Catch::StartsWith(path));
      const std::string null = error_of(with_key(section.path, spec.name, nullptr));
      if (spec.nullable)
        CHECK(null.empty());
      else
        CHECK_THAT(null, Catch::StartsWith(path) && Catch::EndsWith("found null"));
    }
  }
}

TEST_CASE("an unknown key in a section is named with its path", "[scenario][sections]") {
  for (const ScenarioSection& section : scenario_sections()) {
    INFO(section.path);
    const std::string e = error_of(with_key(section.path, "colour", 1));
    CHECK_THAT(e, Catch::StartsWith("s.json: $." + section.path + ".colour: unknown key"));
  }
  CHECK_THAT(error_of(with_key("sensor", "noise.sd", 1)),
             Catch::StartsWith("s.json: $.sensor.noise.sd: unknown key \"sd\""));
  // A nested object's key without a default is required in it.
  nlohmann::json j = nlohmann::json::parse(kBase);
  j["sensor"]["noise"] = nlohmann::json::object();
  CHECK_THAT(error_of(j), Catch::StartsWith("s.json: $.sensor.noise: missing required key"));
}

TEST_CASE("the sections' own rules stay: loop1_period in periodic mode, infinite range as null",
          "[scenario][sections]") {
  nlohmann::json j = with_key("loops", "loop1_period", 2.0);
  j["loops"].erase("mode");
  CHECK_THAT(error_of(j),
             Catch::StartsWith("s.json: $.loops.loop1_period: loop1_period applies to \"mode\": "
                               "\"periodic\" only"));
  CHECK(std::isinf(parse(with_key("sensor", "range", nullptr)).coverage.sensor.range));
  CHECK(parse(with_key("sensor", "range", 0.0)).coverage.sensor.range == 0.0);
  // null: the default, for the tolerances; the ideal network, for the whole network.
  CHECK_FALSE(parse(with_key("convergence", "position_tolerance", nullptr))
                  .coverage.position_tolerance.has_value());
  nlohmann::json ideal = nlohmann::json::parse(kBase);
  ideal["network"] = nullptr;
  CHECK(parse(ideal).coverage.network.channel.is_ideal());
  CHECK_FALSE(describe_scenario(parse(ideal)).contains("network"));
}

TEST_CASE("the loop schedule by its ratio: loop1_period = ratio x loop2_period",
          "[scenario][sections]") {
  nlohmann::json j = nlohmann::json::parse(kBase);
  j["loops"] = {{"mode", "periodic"}, {"loop2_period", 0.05}, {"ratio", 10}};
  const Scenario s = parse(j);
  CHECK(s.coverage.loop1_period == SimTime::from_seconds(0.5));
  // Written back as the period it set, and loads back the same.
  const nlohmann::json described = describe_scenario(s);
  CHECK(described["loops"]["loop1_period"] == 0.5);
  CHECK_FALSE(described["loops"].contains("ratio"));
  CHECK(parse(described).coverage.loop1_period == s.coverage.loop1_period);
  // One of the two; periodic only; a period a run resolves.
  j["loops"]["loop1_period"] = 0.5;
  CHECK_THAT(error_of(j), Catch::Contains("$.loops.loop1_period: give loop1_period or ratio, "
                                          "not both"));
  j["loops"].erase("loop1_period");
  j["loops"]["mode"] = "classic";
  CHECK_THAT(error_of(j),
             Catch::Contains("$.loops.ratio: ratio applies to \"mode\": \"periodic\" only"));
  j["loops"]["mode"] = "periodic";
  j["loops"]["ratio"] = 1e9;
  CHECK_THAT(error_of(j), Catch::Contains("outside the periods a run resolves"));
  // null: not set, so that a sweep's zip can pair it with the classic schedule.
  for (const char* key : {"ratio", "loop1_period"}) {
    nlohmann::json classic = nlohmann::json::parse(kBase);
    classic["loops"] = {{"mode", "classic"}, {key, nullptr}};
    CHECK(error_of(classic).empty());
  }
}

TEST_CASE("every key set away from its default is described and loads back the same",
          "[scenario][sections][describe]") {
  nlohmann::json j = nlohmann::json::parse(kBase);
  j["robots"]["positions"] = {{0.5, 0.5}, {3.0, 3.0}};
  j["loops"]["mode"] = "periodic";
  for (const ScenarioSection& section : scenario_sections()) {
    for (const ConfigKey<Scenario>& k : section.keys) {
      const std::string& name = k.spec.name;
      // separation goes with drawn robots, jitter is drawn already when written back.
      if (section.path == "robots" && name != "max_speed") continue;
      if (name == "mode") continue;
      // ratio excludes loop1_period, set here: its own test below.
      if (section.path == "loops" && name == "ratio") continue;
      // Mapping refuses the known projection and range noise set here: its own test below.
      if (section.path == "environment" || section.path == "mapping") continue;
      const nlohmann::json v = other_value(k.spec);
      const auto dot = name.find('.');
      if (dot == std::string::npos)
        j[section.path][name] = v;
      else
        j[section.path][name.substr(0, dot)][name.substr(dot + 1)] = v;
    }
  }
  INFO(j.dump());
  const Scenario s = parse(j);
  CHECK(s.coverage.mode == LoopMode::periodic);
  CHECK(s.coverage.sensor.noise_sigma == 0.5);
  CHECK(s.recording.compress);
  CHECK(s.coverage.network.channel.line_of_sight);
  CHECK(s.coverage.projection == ProjectionPolicy::known);
  const nlohmann::json described = describe_scenario(s);
  const RunShape shape{*s.environment, s.robot_positions.size()};
  for (const ScenarioSection& section : scenario_sections()) {
    for (const ConfigKey<Scenario>& k : section.keys) {
      INFO(section.path << "." << k.spec.name);
      const std::optional<ParamValue> v = k.get(s, shape);
      if (!v) continue;
      const std::string& name = k.spec.name;
      const auto dot = name.find('.');
      const nlohmann::json& at =
          dot == std::string::npos
              ? described.at(section.path).at(name)
              : described.at(section.path).at(name.substr(0, dot)).at(name.substr(dot + 1));
      CHECK(at == nlohmann::json::parse(param_to_json(*v).dump()));
    }
  }
  const Scenario again = parse(described);
  CHECK(nlohmann::json(describe_scenario(again)) == nlohmann::json(described));
}

TEST_CASE("a key's unit comes from its schema", "[scenario][sections]") {
  CHECK(scenario_key_unit("sensor.range") == "m");
  CHECK(scenario_key_unit("sensor.noise.sigma") == "m");
  CHECK(scenario_key_unit("loops.loop2_period") == "s");
  CHECK(scenario_key_unit("robots.max_speed") == "m/s");
  CHECK(scenario_key_unit("network.acquire_timeout") == "s");
  CHECK(scenario_key_unit("sensor.dropout").empty());
  // Components: any registered type's parameter of that name.
  CHECK(scenario_key_unit("planner.resolution") == "m");
  CHECK(scenario_key_unit("planner.grid_astar.resolution") == "m");
  CHECK(scenario_key_unit("network.delay.value") == "s");
  CHECK(scenario_key_unit("network.loss.p").empty());
  CHECK(scenario_key_unit("sensor.colour").empty());
}

TEST_CASE("docs/scenario-format.md's key tables are the schemas'", "[scenario][sections][docs]") {
  const std::string text = doc("scenario-format.md");
  for (const DocTable& table : scenario_doc_tables()) {
    INFO("section " << table.name
                    << ": regenerate with covsim list --update-docs docs/scenario-format.md");
    const std::optional<std::string> written = doc_table_in(text, table.name);
    REQUIRE(written.has_value());
    CHECK(*written == table.markdown);
  }
  // Replacing a table keeps the prose around it.
  const std::string page = "before\n<!-- begin sensor -->\nold\n<!-- end sensor -->\nafter\n";
  const DocTable sensor{"sensor", "| new |\n"};
  CHECK(with_doc_table(page, sensor) ==
        "before\n<!-- begin sensor -->\n| new |\n<!-- end sensor -->\nafter\n");
  CHECK_THROWS_AS(with_doc_table("no markers", sensor), std::invalid_argument);
}
