#include "analysis/records/run_files.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <string_view>

#include "analysis/records/result_fields.hpp"
#include "scenarios/json_reader.hpp"
#include "scenarios/scenario_error.hpp"

namespace covsim {

namespace fs = std::filesystem;

namespace {

// A file's lines, decompressed if it is gzip (zlib reads any other file as it is).
class LineReader {
 public:
  explicit LineReader(const fs::path& file) : file_(file), in_(gzopen(file.c_str(), "rb")) {
    if (in_ == nullptr) throw ScenarioError(file.string() + ": cannot open");
    gzbuffer(in_, 1 << 17);
  }
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;
  ~LineReader() { gzclose(in_); }

  // The next line without its '\n', as std::getline gives it; false at the end.
  bool next(std::string& line) {
    for (;;) {
      const std::size_t nl = buffer_.find('\n', begin_);
      if (nl != std::string::npos) {
        line.assign(buffer_, begin_, nl - begin_);
        begin_ = nl + 1;
        return true;
      }
      if (end_) {
        if (begin_ == buffer_.size()) return false;
        line.assign(buffer_, begin_);
        begin_ = buffer_.size();
        return true;
      }
      // A row is a few hundred bytes: a line without end (/dev/zero) is not a run's file.
      if (buffer_.size() - begin_ > kMaxLineBytes)
        throw ScenarioError(file_.string() +
                            ": a line longer than 1 MiB (not a file covsim wrote)");
      fill();
    }
  }

 private:
  void fill() {
    buffer_.erase(0, begin_);
    begin_ = 0;
    const std::size_t kept = buffer_.size();
    constexpr unsigned kChunk = 1 << 16;
    buffer_.resize(kept + kChunk);
    const int n = gzread(in_, buffer_.data() + kept, kChunk);
    int error = Z_OK;
    std::string_view message = gzerror(in_, &error);
    // A truncated or corrupt .gz is an error, not a shorter file. zlib's message starts with
    // the file's name.
    if (n < 0 || (error != Z_OK && error != Z_STREAM_END)) {
      const std::string name = file_.string() + ": ";
      if (message.starts_with(name)) message.remove_prefix(name.size());
      throw ScenarioError(name + "cannot read: " + std::string(message));
    }
    buffer_.resize(kept + static_cast<std::size_t>(n));
    end_ = n == 0;
  }

  static constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;
  fs::path file_;
  gzFile in_;
  std::string buffer_;
  std::size_t begin_ = 0;
  bool end_ = false;
};

// The fields of each data line of a CSV file (or gzipped CSV) with the expected header.
template <class F>
void read_csv(const fs::path& file, const std::string& header_prefix, std::size_t fields, F&& row) {
  LineReader in(file);
  std::string line;
  if (!in.next(line) || line.rfind(header_prefix, 0) != 0)
    throw ScenarioError(
        fmt::format("{}:1: expected a header starting \"{}\"", file.string(), header_prefix));
  std::vector<double> v;
  for (std::size_t n = 2; in.next(line); ++n) {
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
    if (v == nullptr && f.added_later) continue;
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
    // Only how they were drawn is replaced; their speed, body, localization and the rest
    // stay.
    nlohmann::json& robots = j["robots"];
    for (const char* drawn : {"count", "start", "separation", "jitter"})
      robots.erase(drawn);
    robots["positions"] = nlohmann::json::array();
    for (Vec2 p : scenario.robot_positions)
      robots["positions"].push_back({p.x, p.y});
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

bool is_record_file(const std::string& name) {
  if (name.ends_with(".partial")) return true;
  // Both trajectory names: a compressed run replaces an uncompressed one's file, and back.
  for (std::string_view f :
       {std::string_view("scenario.json"), std::string_view("final.json"),
        trajectory_file_name(false), trajectory_file_name(true), std::string_view("metrics.csv"),
        std::string_view("map.csv"), std::string_view("planner_map.csv")})
    if (name == f || name == std::string(f) + "-metadata.json") return true;
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
  const fs::path plain = dir / trajectory_file_name(false);
  const fs::path compressed = dir / trajectory_file_name(true);
  std::error_code ec;
  const bool has_compressed = fs::exists(compressed, ec);
  // `covsim run` leaves one of them; with both, which one is the run's is unknown.
  if (has_compressed && fs::exists(plain, ec)) {
    throw ScenarioError(fmt::format("{}: holds both {} and {}; remove the one not of this run",
                                    dir.string(), plain.filename().string(),
                                    compressed.filename().string()));
  }
  const fs::path trajectory = has_compressed ? compressed : plain;
  read_csv(trajectory, trajectory_header(), kTrajectoryColumns.size(),
           [&](const std::vector<double>& v) {
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
  // map.csv: the cells' size is the lattice's over Ω's box.
  const fs::path map = dir / "map.csv";
  if (fs::exists(map)) {
    const Vec2 box = f.scenario.environment->bounds().size();
    f.known.size = std::max(box.x, box.y) / std::floor(f.scenario.coverage.mapping.cells);
    // Per robot columns r0, r1, ... after t, with mapping.robot_maps.
    std::string header;
    LineReader(map).next(header);
    const std::size_t robots =
        static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) - 2;
    f.known.robots.assign(robots, {});
    read_csv(map, "x,y,t", 3 + robots, [&](const std::vector<double>& v) {
      f.known.cells.push_back({{v[0], v[1]}, v[2]});
      for (std::size_t r = 0; r < robots; ++r)
        f.known.robots[r].push_back(v[3 + r]);
    });
  }
  // planner_map.csv: what the planners with maps of their own planned on, over the run.
  const fs::path pictures = dir / "planner_map.csv";
  if (fs::exists(pictures)) {
    LineReader lines(pictures);
    std::string line;
    lines.next(line);
    if (line != PlannerMapRecord::kHeader)
      throw ScenarioError(fmt::format("{}: expected the header {}, found \"{}\"", pictures.string(),
                                      PlannerMapRecord::kHeader, line));
    const std::size_t robots = f.outcome.robots.size();
    PlannerMapRecord& r = f.planner_maps;
    for (std::size_t row = 2; lines.next(line); ++row) {
      std::istringstream in(line);
      std::string field[7];
      for (std::string& s : field)
        std::getline(in, s, ',');
      const auto bad = [&](std::string_view why) {
        return ScenarioError(fmt::format(
            "{}:{}: {}: expected robot,wall|path|stop,t,x0,y0,x1,y1 (robot empty for a shared "
            "map's wall, no coordinates for a stop), found \"{}\"",
            pictures.string(), row, why, line));
      };
      const std::string& kind = field[1];
      if (kind != "wall" && kind != "path" && kind != "stop") throw bad("an unknown kind");
      std::optional<std::uint32_t> robot;
      double t = 0.0, v[4] = {0.0, 0.0, 0.0, 0.0};
      try {
        if (!field[0].empty() || kind != "wall") {
          const unsigned long id = std::stoul(field[0]);
          if (id >= robots) throw bad(fmt::format("no robot {} (the run has {})", id, robots));
          robot = static_cast<std::uint32_t>(id);
        }
        t = std::stod(field[2]);
        if (kind != "stop")
          for (int k = 0; k < 4; ++k)
            v[k] = std::stod(field[3 + k]);
      } catch (const ScenarioError&) {
        throw;
      } catch (const std::exception&) {
        throw bad("a field is not a number");
      }
      if (!std::isfinite(t) || t < 0.0) throw bad("a time that is not a finite t >= 0");
      const double last = std::max(r.walls.empty() ? 0.0 : r.walls.back().t,
                                   r.ways.empty() ? 0.0 : r.ways.back().t);
      if (t < last) throw bad("rows out of time order");
      if (kind == "wall") {
        r.walls.push_back({t, robot, {v[0], v[1]}, {v[2], v[3]}});
      } else if (kind == "stop") {
        r.ways.push_back({t, *robot, {}});
      } else {
        // A way's legs follow one another in rows of one robot and time.
        const bool more = !r.ways.empty() && r.ways.back().robot == *robot &&
                          r.ways.back().t == t && !r.ways.back().points.empty();
        if (!more) r.ways.push_back({t, *robot, {{v[0], v[1]}}});
        r.ways.back().points.push_back({v[2], v[3]});
      }
    }
  }
  return f;
}

}  // namespace covsim
