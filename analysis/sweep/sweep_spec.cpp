#include "analysis/sweep/sweep_spec.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <unordered_map>

#include "io/interrupt.hpp"
#include "scenarios/input_file.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_error.hpp"
#include "scenarios/scenario_override.hpp"

namespace covsim {

namespace {

// Loads every setting's scenario once (with the first seed) before anything runs: a typo in a
// path or a bad value is one error, at the value in the sweep file that caused it. `sweep` is
// the sweep file as read, `named` the scenario file it names (null for an inline scenario).
void validate_settings(const SweepSpec& spec, const std::vector<std::string>& list_paths,
                       std::size_t grid_parameters, std::size_t zip_rows, const InputFile& sweep,
                       const InputFile* named) {
  const auto under = [](const std::string& a, const std::string& b) {
    return a.size() >= b.size() && a.compare(0, b.size(), b) == 0 &&
           (a.size() == b.size() || a[b.size()] == '.' || a[b.size()] == '[');
  };
  const std::string inline_source = spec.source + " (the scenario)";
  for (std::size_t k = 0; k < spec.settings.size(); ++k) {
    // A large grid takes a while to check: SIGINT and SIGTERM stop it between settings.
    if (const int signal = pending_interrupt()) throw Interrupted(signal);
    const SweepRun run{0, k, spec.seeds.front(), spec.settings[k]};
    try {
      parse_scenario(spec.scenario_for(run), named ? named->source : inline_source,
                     spec.scenario_dir);
    } catch (const ScenarioError& e) {
      for (std::size_t p = spec.parameters.size(); p-- > 0;) {
        const std::string at = "$." + spec.parameters[p];
        if (e.path().empty() || !(under(e.path(), at) || (e.path() != "$" && under(at, e.path()))))
          continue;
        // The value's place in its list: a zip row is the innermost index; a grid list has
        // no repeats.
        std::size_t index = k % std::max<std::size_t>(zip_rows, 1);
        if (p < grid_parameters) {
          std::vector<nlohmann::json> seen;
          for (const auto& setting : spec.settings) {
            if (std::find(seen.begin(), seen.end(), setting[p]) == seen.end())
              seen.push_back(setting[p]);
          }
          index = static_cast<std::size_t>(
              std::find(seen.begin(), seen.end(), spec.settings[k][p]) - seen.begin());
        }
        throw ScenarioError(
            spec.source, fmt::format("{}[{}]", list_paths[p], index),
            fmt::format("{} = {} gives an invalid scenario: {}: {}", spec.parameters[p],
                        spec.settings[k][p].dump(), e.path(), e.detail()));
      }
      if (named) {
        throw ScenarioError(spec.source, "$.scenario",
                            fmt::format("the scenario is invalid: {}", named->located(e).what()));
      }
      // An inline scenario's error is placed where its value is in the sweep file.
      const bool inside = e.file() == inline_source && !e.path().empty();
      throw ScenarioError(spec.source,
                          sweep.place_of(inside ? "$.scenario" + e.path().substr(1) : "$.scenario"),
                          "$.scenario", fmt::format("the scenario is invalid: {}", e.what()));
    }
  }
}

SweepSpec read_sweep(const InputFile& in, const std::filesystem::path& file) {
  SweepSpec spec;
  spec.source = in.source;
  const JsonValue root(in.json, spec.source);
  root.only_keys({"scenario", "grid", "zip", "seeds"});
  const JsonValue scenario = root.at("scenario");
  std::optional<InputFile> named;
  if (scenario.raw().is_string()) {
    const std::filesystem::path path = file.parent_path() / scenario.string();
    named = read_input(path);
    spec.scenario = named->json;
    spec.scenario_dir = path.parent_path();
  } else if (scenario.raw().is_object()) {
    spec.scenario = scenario.raw();
    spec.scenario_dir = file.parent_path();
  } else {
    scenario.fail("expected a scenario file name or an inline scenario object");
  }

  // Grid: a cartesian product, first key outermost. Each parameter's list and where it is in
  // the file, for errors that name the value at fault.
  std::vector<std::vector<nlohmann::json>> settings{{}};
  std::vector<std::string> list_paths;
  // Repeats found by hashing each value's text (a number as a double: 1 and 1.0 are one
  // value): lists may hold up to a million values.
  const auto no_repeats = [](const JsonValue& values) {
    std::unordered_map<std::string, std::size_t> first;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const nlohmann::json& v = values.raw()[i];
      const auto [at, fresh] =
          first.emplace(v.is_number() ? nlohmann::json(v.get<double>()).dump() : v.dump(), i);
      if (!fresh)
        values[i].fail(
            fmt::format("{} is listed twice (also at [{}])", values.raw()[i].dump(), at->second));
    }
  };
  auto check_key = [&](const JsonValue& where, const std::string& key) {
    if (const std::string e = dotted_path_error(key); !e.empty()) where.fail(e);
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
      no_repeats(values);
      if (settings.size() > kMaxSweepRuns / values.size())  // refused before it is built
        values.fail(
            fmt::format("the grid would have more than {} settings (a sweep holds at "
                        "most {} runs)",
                        kMaxSweepRuns, kMaxSweepRuns));
      spec.parameters.push_back(key);
      list_paths.push_back(values.path());
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
  const std::size_t grid_parameters = spec.parameters.size();
  std::size_t zip_rows = 0;
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
      list_paths.push_back(values.path());
      columns.emplace_back(key, list);
    }
    std::unordered_map<std::string, std::size_t> first_row;
    for (std::size_t r = 0; r < rows; ++r) {
      nlohmann::json row = nlohmann::json::array();
      for (const auto& [key, list] : columns)
        row.push_back(list[r]);
      const auto [at, fresh] = first_row.emplace(row.dump(), r);
      if (!fresh) zip->fail(fmt::format("rows {} and {} are the same setting", at->second, r));
    }
    zip_rows = columns.empty() ? 0 : rows;
    if (rows != 0 && settings.size() > kMaxSweepRuns / rows)
      zip->fail(
          fmt::format("grid and zip would have more than {} settings (a sweep holds at "
                      "most {} runs)",
                      kMaxSweepRuns, kMaxSweepRuns));
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
    std::unordered_map<std::uint64_t, std::size_t> first_seed;
    for (std::size_t i = 0; i < seeds.size(); ++i) {
      const std::uint64_t seed = seeds[i].unsigned_integer();
      const auto [at, fresh] = first_seed.emplace(seed, i);
      if (!fresh)
        seeds[i].fail(fmt::format("seed {} is listed twice (also at [{}])", seed, at->second));
      spec.seeds.push_back(seed);
    }
    if (spec.seeds.empty()) seeds.fail("expected at least one seed");
  } else {
    seeds.only_keys({"count"});
    const std::uint64_t n = seeds.at("count").unsigned_integer();
    if (n == 0 || n > kMaxSweepRuns)
      seeds.at("count").fail(fmt::format("expected a count between 1 and {}", kMaxSweepRuns));
    for (std::uint64_t s = 1; s <= n; ++s)
      spec.seeds.push_back(s);
  }
  if (spec.settings.size() > kMaxSweepRuns / spec.seeds.size())
    seeds.fail(fmt::format("{} settings × {} seeds is more than the {} runs a sweep holds",
                           spec.settings.size(), spec.seeds.size(), kMaxSweepRuns));
  validate_settings(spec, list_paths, grid_parameters, zip_rows, in, named ? &*named : nullptr);
  return spec;
}

}  // namespace

SweepSpec load_sweep(const std::filesystem::path& file) {
  const InputFile in = read_input(file);
  try {
    return read_sweep(in, file);
  } catch (const ScenarioError& e) {
    throw in.located(e);
  }
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
  // Written by covsim, but read from a folder a user may have edited or mixed.
  for (std::size_t s = 0; s < spec.settings.size(); ++s) {
    if (spec.settings[s].size() != spec.parameters.size())
      throw std::invalid_argument(fmt::format("setting {} has {} values for {} parameters", s,
                                              spec.settings[s].size(), spec.parameters.size()));
  }
  if (spec.settings.empty() || spec.seeds.empty() ||
      spec.settings.size() > kMaxSweepRuns / spec.seeds.size())
    throw std::invalid_argument(fmt::format("{} settings and {} seeds: expected 1 to {} runs",
                                            spec.settings.size(), spec.seeds.size(),
                                            kMaxSweepRuns));
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
    override_scenario(j, parameters[p], run.values[p]);
  j["seed"] = run.seed;
  return j;
}

}  // namespace covsim
