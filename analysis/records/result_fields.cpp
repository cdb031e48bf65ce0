#include "analysis/records/result_fields.hpp"

#include <cmath>

#include "core/fingerprint.hpp"

namespace covsim {

namespace {
using json = nlohmann::ordered_json;

// A value not computed (NaN) is null: an empty cell in CSV.
json number_or_null(double v) {
  return std::isnan(v) ? json(nullptr) : json(v);
}

json point(Vec2 p) {
  return json::array({p.x, p.y});
}
Vec2 point(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 2) throw std::invalid_argument("expected [x, y]");
  return {j.at(0).get<double>(), j.at(1).get<double>()};
}

PlanStatus status_named(const std::string& s) {
  for (PlanStatus p :
       {PlanStatus::moving, PlanStatus::reached, PlanStatus::projected, PlanStatus::stalled}) {
    if (to_string(p) == s) return p;
  }
  throw std::invalid_argument("expected moving, reached, projected or stalled, found \"" + s +
                              "\"");
}

// A field that reads and writes one member.
template <class R, class T>
Field<R> member(std::string name, FieldKind kind, std::string unit, std::string description,
                T R::*m, bool summarized = false) {
  return Field<R>{std::move(name),
                  kind,
                  std::move(unit),
                  std::move(description),
                  [m](const R& r) { return json(r.*m); },
                  [m](R& r, const nlohmann::json& j) { r.*m = j.get<T>(); },
                  summarized};
}
}  // namespace

const FieldTable<RobotOutcome>& robot_fields() {
  using R = RobotOutcome;
  const auto at = [](std::string name, std::string description, Vec2 R::*m) {
    return Field<R>{std::move(name),
                    FieldKind::point,
                    "m",
                    std::move(description),
                    [m](const R& r) { return point(r.*m); },
                    [m](R& r, const nlohmann::json& j) { r.*m = point(j); }};
  };
  static const FieldTable<R> t{
      at("position", "where the robot ended (its real generator)", &R::position),
      at("virtual_generator", "its virtual generator", &R::virtual_generator),
      at("virtual_target", "its last loop-1 target", &R::virtual_target),
      at("real_target", "the virtual target, or its projection onto Ω", &R::real_target),
      member("projected", FieldKind::boolean, "", "the virtual target lies outside Ω",
             &R::projected),
      Field<R>{
          "status", FieldKind::text, "", "the planner's: moving, reached, projected or stalled",
          [](const R& r) { return json(std::string(to_string(r.status))); },
          [](R& r, const nlohmann::json& j) { r.status = status_named(j.get<std::string>()); }},
      member("path_length", FieldKind::number, "m", "distance travelled", &R::path_length),
      member("target_outside_steps", FieldKind::integer, "",
             "loop-2 steps taken while its loop-1 target lay outside Ω", &R::target_outside_steps),
      member("stalled_time", FieldKind::number, "s", "time its planner spent stalled",
             &R::stalled_time),
      member("centroid_distance", FieldKind::number, "m",
             "final distance from the centroid of its cell in the last partition",
             &R::centroid_distance),
  };
  return t;
}

namespace {
template <class R>
Field<R> later(Field<R> f) {
  f.added_later = true;
  return f;
}

// A field for an incident that stopped the run (RobotIncident): null, or its robot, time,
// goal and position.
Field<CoverageOutcome> incident(std::string name, std::string description,
                                std::optional<RobotIncident> CoverageOutcome::*m) {
  using O = CoverageOutcome;
  return Field<O>{std::move(name),
                  FieldKind::json,
                  "",
                  std::move(description),
                  [m](const O& o) -> json {
                    if (!(o.*m)) return nullptr;
                    const RobotIncident& f = *(o.*m);
                    return json{{"robot", f.robot},
                                {"time", f.time.seconds()},
                                {"goal", point(f.goal)},
                                {"position", point(f.position)}};
                  },
                  [m](O& o, const nlohmann::json& j) {
                    if (j.is_null()) {
                      (o.*m).reset();
                      return;
                    }
                    o.*m = RobotIncident{j.at("robot").get<std::uint32_t>(),
                                         SimTime::from_seconds(j.at("time").get<double>()),
                                         point(j.at("goal")), point(j.at("position"))};
                  }};
}
}  // namespace

const FieldTable<CoverageOutcome>& final_fields() {
  using O = CoverageOutcome;
  static const FieldTable<O> t{
      member("scenario", FieldKind::text, "", "the scenario file the run came from", &O::scenario),
      member("converged", FieldKind::boolean, "", "every robot stable", &O::converged),
      Field<O>{"sim_time", FieldKind::number, "s", "simulated time at the end",
               [](const O& o) { return json(o.sim_time.seconds()); },
               [](O& o, const nlohmann::json& j) {
                 o.sim_time = SimTime::from_seconds(j.get<double>());
               }},
      Field<O>{"robots", FieldKind::json, "", "per robot, in scenario order (robot_fields)",
               [](const O& o) {
                 json a = json::array();
                 for (const RobotOutcome& r : o.robots)
                   a.push_back(to_json_object(robot_fields(), r));
                 return a;
               },
               [](O& o, const nlohmann::json& j) {
                 o.robots.clear();
                 for (const auto& rj : j) {
                   RobotOutcome r;
                   for (const auto& f : robot_fields())
                     f.set(r, rj.at(f.name));
                   o.robots.push_back(r);
                 }
               }},
      member("cost.virtual", FieldKind::number, "",
             "H of the virtual generators on their partition", &O::cost_virtual),
      member("cost.real", FieldKind::number, "", "H of the real positions on their partition",
             &O::cost_real),
      member("cost.real_in_virtual_partition", FieldKind::number, "",
             "H of the real positions on the virtual generators' partition",
             &O::cost_real_in_virtual_partition),
      Field<O>{"fingerprint", FieldKind::text, "", "16 hex digits",
               [](const O& o) { return json(Fingerprint::to_hex(o.fingerprint)); },
               [](O& o, const nlohmann::json& j) {
                 o.fingerprint = std::stoull(j.get<std::string>(), nullptr, 16);
               }},
      member("network.decentralized", FieldKind::boolean, "",
             "false for the ideal network (no messages)", &O::decentralized),
      Field<O>{"network.messages_sent", FieldKind::integer, "", "link transmissions",
               [](const O& o) { return json(o.network.sent); },
               [](O& o, const nlohmann::json& j) { o.network.sent = j.get<std::uint64_t>(); }},
      Field<O>{"network.messages_delivered", FieldKind::integer, "", "messages delivered",
               [](const O& o) { return json(o.network.delivered); },
               [](O& o, const nlohmann::json& j) { o.network.delivered = j.get<std::uint64_t>(); }},
      Field<O>{"network.messages_lost", FieldKind::integer, "", "messages lost by the loss model",
               [](const O& o) { return json(o.network.lost); },
               [](O& o, const nlohmann::json& j) { o.network.lost = j.get<std::uint64_t>(); }},
      Field<O>{
          "network.messages_unreachable", FieldKind::integer, "",
          "messages out of range or blocked by walls",
          [](const O& o) { return json(o.network.unreachable); },
          [](O& o, const nlohmann::json& j) { o.network.unreachable = j.get<std::uint64_t>(); }},
      member("convergence.time_to_10_percent", FieldKind::number, "s",
             "from when the real cost stays within 10% of its final value", &O::time_to_10_percent),
      member("convergence.time_to_5_percent", FieldKind::number, "s", "the same within 5%",
             &O::time_to_5_percent),
      member("convergence.time_to_1_percent", FieldKind::number, "s", "the same within 1%",
             &O::time_to_1_percent),
      later(member("convergence.cost_to_best", FieldKind::number, "",
                   "the final real cost over the least one sampled during the run (1: ended at "
                   "its best)",
                   &O::cost_to_best)),
      member("convergence.path_length", FieldKind::number, "m", "all robots' paths",
             &O::path_length),
      member("failures.target_outside_steps", FieldKind::integer, "",
             "loop-2 steps with the loop-1 target outside Ω, all robots", &O::target_outside_steps),
      member("failures.stalled_time", FieldKind::number, "s", "time planners spent stalled",
             &O::stalled_time),
      member("failures.centroid_distance_mean", FieldKind::number, "m",
             "mean final distance from the cell's centroid", &O::centroid_distance_mean),
      member("failures.centroid_distance_max", FieldKind::number, "m",
             "largest final distance from the cell's centroid", &O::centroid_distance_max),
      member("planner.steps", FieldKind::integer, "", "planner steps taken", &O::planner_steps),
      Field<O>{"planner.step_time_us", FieldKind::number, "µs",
               "mean wall-clock time of a planner step (varies between runs)",
               [](const O& o) { return json(o.planner_step_time_us()); },
               [](O& o, const nlohmann::json& j) {
                 o.planner_seconds = j.get<double>() * 1e-6 * static_cast<double>(o.planner_steps);
               }},
      member("stop_reason", FieldKind::text, "",
             "converged, planner_failure, left_environment, stuck or max_time", &O::stop_reason),
      incident("planner_failure",
               "null, or the robot, time, goal and position of a planner failure",
               &O::planner_failure),
      later(incident(
          "left_environment",
          "null, or the robot, time, goal and crossing point of a robot that drove out of Ω",
          &O::left_environment)),
      member("events", FieldKind::integer, "", "events dispatched", &O::events),
      member("seed", FieldKind::integer, "", "the run's seed", &O::seed),
      Field<O>{"provenance", FieldKind::json, "",
               "what built covsim: version, commit, dirty, compiler, build_type, flags",
               [](const O& o) { return json(o.provenance); },
               [](O& o, const nlohmann::json& j) { o.provenance = j; }},
  };
  return t;
}

const FieldTable<MetricsSample>& metrics_fields() {
  using S = MetricsSample;
  const auto get = [](std::string name, FieldKind kind, std::string unit, std::string description,
                      std::function<json(const S&)> g) {
    return Field<S>{std::move(name),        kind,         std::move(unit),
                    std::move(description), std::move(g), nullptr};
  };
  static const FieldTable<S> t{
      member("t", FieldKind::number, "s", "sample time", &S::t),
      member("cost_real", FieldKind::number, "", "H of the real positions", &S::cost_real),
      member("cost_virtual", FieldKind::number, "", "H of the virtual generators",
             &S::cost_virtual),
      member("cost_real_in_virtual_partition", FieldKind::number, "",
             "H of the real positions on the virtual partition",
             &S::cost_real_in_virtual_partition),
      member("settled", FieldKind::integer, "", "robots whose planner has settled", &S::settled),
      member("projected", FieldKind::integer, "", "robots whose virtual target lies outside Ω",
             &S::projected),
      member("path_length", FieldKind::number, "m", "distance travelled by all robots",
             &S::path_length),
      get("messages_sent", FieldKind::integer, "", "link transmissions so far",
          [](const S& s) { return json(s.messages.sent); }),
      get("messages_delivered", FieldKind::integer, "", "messages delivered so far",
          [](const S& s) { return json(s.messages.delivered); }),
      get("messages_lost", FieldKind::integer, "", "messages lost so far",
          [](const S& s) { return json(s.messages.lost); }),
      get("info_age_mean", FieldKind::number, "s", "mean age of neighbour-table entries",
          [](const S& s) { return json(s.network.info_age_mean); }),
      get("info_age_max", FieldKind::number, "s", "largest age of a neighbour-table entry",
          [](const S& s) { return json(s.network.info_age_max); }),
      get("area_claimed_by_none", FieldKind::number, "m²", "area of Ω in no robot's own cell",
          [](const S& s) { return json(s.network.area_claimed_by_none); }),
      get("area_claimed_by_several", FieldKind::number, "m²",
          "area of Ω in two or more robots' own cells",
          [](const S& s) { return json(s.network.area_claimed_by_several); }),
      get("components", FieldKind::integer, "", "connected components of the communication graph",
          [](const S& s) { return json(s.network.graph.components); }),
      get("largest_component", FieldKind::integer, "", "robots in the largest component",
          [](const S& s) { return json(s.network.graph.largest_component); }),
      get("diameter_hops", FieldKind::integer, "", "largest hop distance between reachable robots",
          [](const S& s) { return json(s.network.graph.diameter); }),
      get("average_degree", FieldKind::number, "", "mean number of neighbours",
          [](const S& s) { return json(s.network.graph.average_degree); }),
      get("algebraic_connectivity", FieldKind::number, "",
          "second-smallest eigenvalue of the graph Laplacian",
          [](const S& s) { return number_or_null(s.network.graph.algebraic_connectivity); }),
  };
  return t;
}

const FieldTable<RunMeasures>& run_fields() {
  using M = RunMeasures;
  const auto f = [](std::string name, FieldKind kind, std::string unit, std::string description,
                    std::function<json(const CoverageOutcome&)> g, bool summarized) {
    return Field<M>{std::move(name),
                    kind,
                    std::move(unit),
                    std::move(description),
                    [g = std::move(g)](const M& m) { return g(m.outcome); },
                    nullptr,
                    summarized};
  };
  // A communication measure of the run (sim/metrics_sampler.hpp), summarised.
  const auto c = [](std::string name, std::string unit, std::string description,
                    double CommunicationSummary::*m) {
    return Field<M>{std::move(name),
                    FieldKind::number,
                    std::move(unit),
                    std::move(description),
                    [m](const M& r) { return number_or_null(r.communication.*m); },
                    nullptr,
                    true};
  };
  using O = CoverageOutcome;
  static const FieldTable<M> t{
      f(
          "converged", FieldKind::boolean, "", "1 if every robot ended stable",
          [](const O& o) { return json(o.converged); }, false),
      f(
          "sim_time", FieldKind::number, "s", "simulated time at the end",
          [](const O& o) { return json(o.sim_time.seconds()); }, true),
      f(
          "cost_virtual", FieldKind::number, "", "final H of the virtual generators",
          [](const O& o) { return json(o.cost_virtual); }, true),
      f(
          "cost_real", FieldKind::number, "", "final H of the real positions",
          [](const O& o) { return json(o.cost_real); }, true),
      f(
          "cost_real_in_virtual_partition", FieldKind::number, "",
          "final H of the real positions on the virtual partition",
          [](const O& o) { return json(o.cost_real_in_virtual_partition); }, true),
      f(
          "path_length", FieldKind::number, "m", "all robots' paths",
          [](const O& o) { return json(o.path_length); }, true),
      f(
          "time_to_10_percent", FieldKind::number, "s", "settling within 10% of the final cost",
          [](const O& o) { return json(o.time_to_10_percent); }, true),
      f(
          "time_to_5_percent", FieldKind::number, "s", "settling within 5%",
          [](const O& o) { return json(o.time_to_5_percent); }, true),
      f(
          "time_to_1_percent", FieldKind::number, "s", "settling within 1%",
          [](const O& o) { return json(o.time_to_1_percent); }, true),
      f(
          "cost_to_best", FieldKind::number, "",
          "the final real cost over the least sampled during the run",
          [](const O& o) { return json(o.cost_to_best); }, true),
      f(
          "messages_sent", FieldKind::integer, "", "link transmissions",
          [](const O& o) { return json(o.network.sent); }, false),
      f(
          "messages_delivered", FieldKind::integer, "", "messages delivered",
          [](const O& o) { return json(o.network.delivered); }, true),
      f(
          "messages_lost", FieldKind::integer, "", "messages lost by the loss model",
          [](const O& o) { return json(o.network.lost); }, true),
      f(
          "messages_unreachable", FieldKind::integer, "",
          "transmissions out of range or blocked by walls",
          [](const O& o) { return json(o.network.unreachable); }, true),
      c("info_age_mean", "s", "mean age of neighbour-table entries, over the samples",
        &CommunicationSummary::info_age_mean),
      c("info_age_max", "s", "largest age of a neighbour-table entry",
        &CommunicationSummary::info_age_max),
      c("area_claimed_by_none", "m²",
        "mean area of Ω in no robot's own cell (cells from each robot's table), over the samples",
        &CommunicationSummary::area_claimed_by_none),
      c("area_claimed_by_several", "m²", "mean area of Ω in two or more robots' own cells",
        &CommunicationSummary::area_claimed_by_several),
      c("connected_fraction", "",
        "fraction of the samples at which the communication graph was connected",
        &CommunicationSummary::connected_fraction),
      c("algebraic_connectivity_min", "", "least algebraic connectivity of the communication graph",
        &CommunicationSummary::algebraic_connectivity_min),
      f(
          "events", FieldKind::integer, "", "events dispatched",
          [](const O& o) { return json(o.events); }, false),
      f(
          "stop_reason", FieldKind::text, "",
          "converged, planner_failure, left_environment, stuck or max_time",
          [](const O& o) { return json(o.stop_reason); }, false),
      f(
          "target_outside_steps", FieldKind::integer, "",
          "loop-2 steps with the loop-1 target outside Ω, all robots",
          [](const O& o) { return json(o.target_outside_steps); }, true),
      f(
          "stalled_time", FieldKind::number, "s", "time planners spent stalled",
          [](const O& o) { return json(o.stalled_time); }, true),
      f(
          "centroid_distance", FieldKind::number, "m",
          "mean final distance from the cell's centroid",
          [](const O& o) { return json(o.centroid_distance_mean); }, true),
      f(
          "planner_step_time", FieldKind::number, "µs", "mean wall-clock time of a planner step",
          [](const O& o) { return json(o.planner_step_time_us()); }, true),
      Field<M>{"wall_time", FieldKind::number, "s", "wall-clock time of the run",
               [](const M& m) { return json(m.wall_time); }, nullptr, true},
      f(
          "fingerprint", FieldKind::text, "", "16 hex digits",
          [](const O& o) { return json(Fingerprint::to_hex(o.fingerprint)); }, false),
  };
  return t;
}

}  // namespace covsim
