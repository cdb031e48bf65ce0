#include "analysis/sweep_spec.hpp"

#include <fmt/format.h>

#include "scenarios/json_reader.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim {

void set_dotted(nlohmann::json& j, const std::string& dotted, const nlohmann::json& value) {
  nlohmann::json* at = &j;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = dotted.find('.', start);
    const std::string key =
        dotted.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!at->is_object()) *at = nlohmann::json::object();
    if (dot == std::string::npos) {
      (*at)[key] = value;
      return;
    }
    at = &(*at)[key];
    start = dot + 1;
  }
}

SweepSpec load_sweep(const std::filesystem::path& file) {
  SweepSpec spec;
  spec.source = file.string();
  const nlohmann::json j = read_json_file(file);
  const JsonValue root(j, spec.source);
  root.only_keys({"scenario", "grid", "zip", "seeds"});
  const JsonValue scenario = root.at("scenario");
  if (scenario.raw().is_string()) {
    const std::filesystem::path path = file.parent_path() / scenario.string();
    spec.scenario = read_json_file(path);
    spec.scenario_dir = path.parent_path();
  } else if (scenario.raw().is_object()) {
    spec.scenario = scenario.raw();
    spec.scenario_dir = file.parent_path();
  } else {
    scenario.fail("expected a scenario file name or an inline scenario object");
  }

  // Grid: a cartesian product, first key outermost.
  std::vector<std::vector<nlohmann::json>> settings{{}};
  auto check_key = [&](const JsonValue& where, const std::string& key) {
    if (key.empty() || key.front() == '.' || key.back() == '.' ||
        key.find("..") != std::string::npos) {
      where.fail(fmt::format("\"{}\" is not a dotted path like \"network.loss.p\"", key));
    }
    if (key == "seed") where.fail("\"seed\" is set by \"seeds\", not by the grid");
    for (const auto& p : spec.parameters) {
      if (p == key) where.fail(fmt::format("\"{}\" is swept twice", key));
    }
  };
  if (auto grid = root.find("grid")) {
    if (!grid->raw().is_object()) grid->fail("expected an object of dotted paths to value lists");
    for (const auto& [key, list] : grid->raw().items()) {
      const JsonValue values = *grid->find(key);
      check_key(values, key);
      if (values.size() == 0) values.fail("expected at least one value");
      spec.parameters.push_back(key);
      std::vector<std::vector<nlohmann::json>> next;
      for (const auto& s : settings) {
        for (const auto& v : list) {
          next.push_back(s);
          next.back().push_back(v);
        }
      }
      settings.swap(next);
    }
  }
  if (auto zip = root.find("zip")) {
    if (!zip->raw().is_object()) zip->fail("expected an object of dotted paths to value lists");
    std::size_t rows = 0;
    std::vector<std::pair<std::string, nlohmann::json>> columns;
    for (const auto& [key, list] : zip->raw().items()) {
      const JsonValue values = *zip->find(key);
      check_key(values, key);
      if (values.size() == 0) values.fail("expected at least one value");
      if (rows != 0 && values.size() != rows)
        values.fail(fmt::format("expected {} values, as the other zip lists", rows));
      rows = values.size();
      spec.parameters.push_back(key);
      columns.emplace_back(key, list);
    }
    if (!columns.empty()) {
      std::vector<std::vector<nlohmann::json>> next;
      for (const auto& s : settings) {
        for (std::size_t r = 0; r < rows; ++r) {
          next.push_back(s);
          for (const auto& [key, list] : columns)
            next.back().push_back(list[r]);
        }
      }
      settings.swap(next);
    }
  }
  spec.settings = std::move(settings);

  const JsonValue seeds = root.at("seeds");
  if (seeds.raw().is_array()) {
    for (std::size_t i = 0; i < seeds.size(); ++i)
      spec.seeds.push_back(seeds[i].unsigned_integer());
    if (spec.seeds.empty()) seeds.fail("expected at least one seed");
  } else {
    seeds.only_keys({"count"});
    const std::uint64_t n = seeds.at("count").unsigned_integer();
    if (n == 0 || n > 1'000'000) seeds.at("count").fail("expected a count between 1 and 1000000");
    for (std::uint64_t s = 1; s <= n; ++s)
      spec.seeds.push_back(s);
  }
  return spec;
}

nlohmann::json to_json(const SweepSpec& spec) {
  return nlohmann::json{{"source", spec.source},
                        {"scenario", spec.scenario},
                        {"scenario_dir", spec.scenario_dir.string()},
                        {"parameters", spec.parameters},
                        {"settings", spec.settings},
                        {"seeds", spec.seeds}};
}

SweepSpec sweep_from_json(const nlohmann::json& j) {
  SweepSpec spec;
  spec.source = j.at("source").get<std::string>();
  spec.scenario = j.at("scenario");
  spec.scenario_dir = j.at("scenario_dir").get<std::string>();
  spec.parameters = j.at("parameters").get<std::vector<std::string>>();
  spec.settings = j.at("settings").get<std::vector<std::vector<nlohmann::json>>>();
  spec.seeds = j.at("seeds").get<std::vector<std::uint64_t>>();
  return spec;
}

std::vector<SweepRun> SweepSpec::runs() const {
  std::vector<SweepRun> out;
  for (std::size_t s = 0; s < settings.size(); ++s) {
    for (std::uint64_t seed : seeds)
      out.push_back(SweepRun{out.size(), s, seed, settings[s]});
  }
  return out;
}

nlohmann::json SweepSpec::scenario_for(const SweepRun& run) const {
  nlohmann::json j = scenario;
  for (std::size_t p = 0; p < parameters.size(); ++p)
    set_dotted(j, parameters[p], run.values[p]);
  j["seed"] = run.seed;
  return j;
}

}  // namespace covsim
