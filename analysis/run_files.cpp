#include "analysis/run_files.hpp"

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <sstream>

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

Vec2 point(const JsonValue& v) {
  const std::vector<double> xy = {v[0].number(), v[1].number()};
  return {xy[0], xy[1]};
}

PlanStatus status_named(const JsonValue& v) {
  const std::string s = v.one_of({"moving", "reached", "projected", "stalled"});
  for (PlanStatus p : {PlanStatus::moving, PlanStatus::reached, PlanStatus::projected})
    if (to_string(p) == s) return p;
  return PlanStatus::stalled;
}

}  // namespace

nlohmann::json portable_scenario(const Scenario& scenario, const fs::path& dir) {
  nlohmann::json j = scenario.json;
  if (j.contains("density") && j["density"].contains("file") && j["density"]["file"].is_string()) {
    const fs::path f = j["density"]["file"].get<std::string>();
    if (f.is_relative()) j["density"]["file"] = fs::absolute(dir / f).string();
  }
  return j;
}

std::vector<std::vector<Vec2>> RunFiles::paths(Vec2 TrajectoryRow::*point) const {
  std::vector<std::vector<Vec2>> out(outcome.robots.size());
  for (const TrajectoryRow& r : trajectory) {
    auto& p = out.at(r.robot);
    if (p.empty() || !(p.back() == r.*point)) p.push_back(r.*point);
  }
  return out;
}

RunFiles read_run_files(const fs::path& dir) {
  RunFiles f;
  const fs::path final_file = dir / "final.json";
  const nlohmann::json fj = read_json_file(final_file);
  const JsonValue final_json(fj, final_file.string());
  const std::string source = final_json.at("scenario").string();
  const fs::path scenario_file = dir / "scenario.json";
  f.scenario = parse_scenario(read_json_file(scenario_file), source, dir);

  CoverageOutcome& o = f.outcome;
  o.converged = final_json.at("converged").boolean();
  o.sim_time = SimTime::from_seconds(final_json.at("sim_time").number());
  o.stop_reason = final_json.at("stop_reason").string();
  const JsonValue cost = final_json.at("cost");
  o.cost_virtual = cost.at("virtual").number();
  o.cost_real = cost.at("real").number();
  o.cost_real_in_virtual_partition = cost.at("real_in_virtual_partition").number();
  const JsonValue robots = final_json.at("robots");
  for (std::size_t i = 0; i < robots.size(); ++i) {
    const JsonValue r = robots[i];
    RobotOutcome ro;
    ro.position = point(r.at("position"));
    ro.virtual_generator = point(r.at("virtual_generator"));
    ro.virtual_target = point(r.at("virtual_target"));
    ro.real_target = point(r.at("real_target"));
    ro.projected = r.at("projected").boolean();
    ro.status = status_named(r.at("status"));
    ro.path_length = r.at("path_length").number();
    o.robots.push_back(ro);
  }
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
  read_csv(dir / "metrics.csv", "t,cost_real,cost_virtual,cost_real_in_virtual_partition", 4,
           [&](const std::vector<double>& v) {
             MetricsSample s{};
             s.t = v[0];
             s.cost_real = v[1];
             s.cost_virtual = v[2];
             s.cost_real_in_virtual_partition = v[3];
             f.samples.push_back(s);
           });
  return f;
}

}  // namespace covsim
