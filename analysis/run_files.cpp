#include "analysis/run_files.hpp"

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <sstream>

#include "analysis/canvas.hpp"
#include "analysis/result_fields.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim {

namespace fs = std::filesystem;

namespace {

// The fields of each data line of a CSV file with the expected header.
template <class F>
void read_csv(const fs::path& file, const std::string& header_prefix, std::size_t fields, F&& row) {
  std::ifstream in(file);
  if (!in) throw ScenarioError(file.string() + ": cannot open");
  std::string line;
  if (!std::getline(in, line) || line.rfind(header_prefix, 0) != 0)
    throw ScenarioError(
        fmt::format("{}:1: expected a header starting \"{}\"", file.string(), header_prefix));
  std::vector<double> v;
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    v.clear();
    const char* p = line.data();
    const char* end = p + line.size();
    while (v.size() < fields) {
      double x = 0;
      const auto r = std::from_chars(p, end, x);
      if (r.ec != std::errc()) {
        throw ScenarioError(
            fmt::format("{}:{}: expected {} numbers, got \"{}\"", file.string(), n, fields, line));
      }
      v.push_back(x);
      p = r.ptr;
      if (p < end && *p == ',') ++p;
    }
    row(v);
  }
}

// Every field of a table from a JSON object, with errors naming the file and JSON path.
template <class Record>
void read_fields(const FieldTable<Record>& table, const nlohmann::json& j, const fs::path& file,
                 Record& out) {
  for (const auto& f : table) {
    if (!f.set) continue;
    const nlohmann::json* v = at_path(j, f.name);
    if (v == nullptr)
      throw ScenarioError(fmt::format("{}: $.{}: missing required key", file.string(), f.name));
    try {
      f.set(out, *v);
    } catch (const std::exception& e) {
      throw ScenarioError(fmt::format("{}: $.{}: {}", file.string(), f.name, e.what()));
    }
  }
}

}  // namespace

nlohmann::json portable_scenario(const Scenario& scenario, const fs::path& dir) {
  nlohmann::json j = scenario.json;
  // Robots drawn per seed are written as drawn: the folder replays without the generator.
  if (j.contains("robots") && j["robots"].is_object() &&
      (j["robots"].contains("count") || j["robots"].contains("jitter"))) {
    nlohmann::json robots{{"positions", nlohmann::json::array()}};
    for (Vec2 p : scenario.robot_positions)
      robots["positions"].push_back({p.x, p.y});
    if (j["robots"].contains("max_speed")) robots["max_speed"] = j["robots"]["max_speed"];
    j["robots"] = robots;
  }
  if (j.contains("density") && j["density"].contains("file") && j["density"]["file"].is_string()) {
    const fs::path f = j["density"]["file"].get<std::string>();
    if (f.is_relative()) j["density"]["file"] = fs::absolute(dir / f).string();
  }
  return j;
}

std::vector<RobotTrack> RunFiles::tracks() const {
  std::vector<RobotTrack> out(outcome.robots.size());
  for (RobotTrack& k : out)
    k.tolerance = track_tolerance(scenario.environment->diameter());
  for (const TrajectoryRow& r : trajectory)
    out.at(r.robot).push(r.t, r.position, r.virtual_generator, r.virtual_target, r.real_target);
  return out;
}

bool is_run_output(const std::string& name) {
  if (name.ends_with(".partial")) return true;
  for (const char* f :
       {"scenario.json", "final.json", "trajectory.csv", "metrics.csv", "replay.html"})
    if (name == f) return true;
  for (const char* stem : {"scene.", "cost."})
    for (FigureFormat format : {FigureFormat::svg, FigureFormat::pdf, FigureFormat::png})
      if (name == stem + std::string(extension(format))) return true;
  return false;
}

RunFiles read_run_files(const fs::path& dir) {
  RunFiles f;
  const fs::path final_file = dir / "final.json";
  const nlohmann::json fj = read_json_file(final_file);
  const std::string source = JsonValue(fj, final_file.string()).at("scenario").string();
  const fs::path scenario_file = dir / "scenario.json";
  f.scenario = parse_scenario(read_json_file(scenario_file), source, dir);

  CoverageOutcome& o = f.outcome;
  read_fields(final_fields(), fj, final_file, o);
  if (o.robots.size() != f.scenario.robot_positions.size()) {
    throw ScenarioError(final_file.string() + ": $.robots: expected as many robots as " +
                        scenario_file.string() + " has");
  }
  const fs::path trajectory = dir / "trajectory.csv";
  read_csv(trajectory, "t,robot,x,y,vx,vy,tx,ty,rx,ry", 10, [&](const std::vector<double>& v) {
    if (!(v[1] >= 0 && v[1] < static_cast<double>(o.robots.size())))
      throw ScenarioError(trajectory.string() + ": robot index out of range");
    f.trajectory.push_back(TrajectoryRow{v[0],
                                         static_cast<std::uint32_t>(v[1]),
                                         {v[2], v[3]},
                                         {v[4], v[5]},
                                         {v[6], v[7]},
                                         {v[8], v[9]}});
  });
  // metrics.csv: the columns the figures need, by their names in the header.
  const fs::path metrics = dir / "metrics.csv";
  std::vector<const Field<MetricsSample>*> columns;
  for (const auto& field : metrics_fields()) {
    if (field.set) columns.push_back(&field);
  }
  std::string wanted;
  for (const auto* c : columns)
    wanted += (wanted.empty() ? "" : ",") + c->name;
  read_csv(metrics, wanted, columns.size(), [&](const std::vector<double>& v) {
    MetricsSample s;
    for (std::size_t k = 0; k < columns.size(); ++k)
      columns[k]->set(s, v[k]);
    f.samples.push_back(s);
  });
  return f;
}

}  // namespace covsim
