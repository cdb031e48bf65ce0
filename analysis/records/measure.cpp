#include "analysis/records/measure.hpp"

#include "analysis/records/json_point.hpp"
#include "analysis/records/result_fields.hpp"
#include "core/fingerprint.hpp"

namespace covsim {

namespace {
using json = nlohmann::ordered_json;
using O = CoverageOutcome;

// A measure of the outcome: final.json's field.
Measure outcome(Field<O> f) {
  Measure m;
  m.name = std::move(f.name);
  m.kind = f.kind;
  m.unit = std::move(f.unit);
  m.description = std::move(f.description);
  m.of_outcome = std::move(f.get);
  m.set = std::move(f.set);
  return m;
}

// A measure of the outcome, read and written by the two functions.
Measure outcome(std::string name, FieldKind kind, std::string unit, std::string description,
                std::function<json(const O&)> get,
                std::function<void(O&, const nlohmann::json&)> set) {
  return outcome(Field<O>{std::move(name), kind, std::move(unit), std::move(description),
                          std::move(get), std::move(set)});
}

// A measure that is one member of the outcome.
template <class T>
Measure member(std::string name, FieldKind kind, std::string unit, std::string description,
               T O::*p) {
  return outcome(member_field(std::move(name), kind, std::move(unit), std::move(description), p));
}

// A number of the outcome that may be missing: NaN in the outcome, null in final.json.
Measure nullable(std::string name, std::string unit, std::string description, double O::*p) {
  return outcome(
      std::move(name), FieldKind::number, std::move(unit), std::move(description),
      [p](const O& o) { return number_or_null(o.*p); },
      [p](O& o, const nlohmann::json& j) { o.*p = j.is_null() ? NAN : j.get<double>(); });
}

// A message total of the run (NetworkTotals).
Measure messages(std::string name, std::string description, std::uint64_t NetworkTotals::*p) {
  return outcome(
      std::move(name), FieldKind::integer, "", std::move(description),
      [p](const O& o) { return json(o.network.*p); },
      [p](O& o, const nlohmann::json& j) { o.network.*p = j.get<std::uint64_t>(); });
}

// A latency of the run's deliveries (NetworkTotals): null without deliveries.
Measure latency(std::string name, std::string description, double NetworkTotals::*p) {
  return outcome(
      std::move(name), FieldKind::number, "s", std::move(description),
      [p](const O& o) { return number_or_null(o.network.*p); },
      [p](O& o, const nlohmann::json& j) { o.network.*p = j.is_null() ? NAN : j.get<double>(); });
}

// A simulated radio's count (RadioTotals): null with the abstract channel.
template <class T>
Measure radio(std::string name, FieldKind kind, std::string description, T RadioTotals::*p) {
  return outcome(
      std::move(name), kind, "", std::move(description),
      [p](const O& o) { return o.network.radio ? json((*o.network.radio).*p) : json(nullptr); },
      [p](O& o, const nlohmann::json& j) {
        if (j.is_null()) return;
        if (!o.network.radio) o.network.radio.emplace();
        (*o.network.radio).*p = j.get<T>();
      });
}

// An incident that stopped the run (RobotIncident): null, or its robot, time, goal and
// position.
Measure incident(std::string name, std::string description, std::optional<RobotIncident> O::*p) {
  return outcome(
      std::move(name), FieldKind::json, "", std::move(description),
      [p](const O& o) -> json {
        if (!(o.*p)) return nullptr;
        const RobotIncident& f = *(o.*p);
        return json{{"robot", f.robot},
                    {"time", f.time.seconds()},
                    {"goal", point_json(f.goal)},
                    {"position", point_json(f.position)}};
      },
      [p](O& o, const nlohmann::json& j) {
        if (j.is_null()) {
          (o.*p).reset();
          return;
        }
        o.*p = RobotIncident{j.at("robot").get<std::uint32_t>(),
                             SimTime::from_seconds(j.at("time").get<double>()),
                             json_point(j.at("goal")), json_point(j.at("position"))};
      });
}

// A measure only a sweep's run records.
Measure of_run(std::string name, std::string unit, std::string description,
               std::function<json(const RunMeasures&)> get) {
  Measure m;
  m.name = std::move(name);
  m.unit = std::move(unit);
  m.description = std::move(description);
  m.of_run = std::move(get);
  return m;
}

// A communication measure of a sweep's run (sim/metrics_sampler.hpp).
Measure communication(std::string name, std::string unit, std::string description,
                      double CommunicationSummary::*p) {
  return of_run(std::move(name), std::move(unit), std::move(description),
                [p](const RunMeasures& r) { return number_or_null(r.communication.*p); });
}
}  // namespace

std::string Measure::column() const {
  return declared_column.empty() ? name.substr(name.rfind('.') + 1) : declared_column;
}

Measure Measure::in_runs(int place, std::string column) && {
  run_place = place;
  declared_column = std::move(column);
  return std::move(*this);
}

Measure Measure::in_summary() && {
  summarized = true;
  return std::move(*this);
}

Measure Measure::later() && {
  added_later = true;
  return std::move(*this);
}

const std::vector<Measure>& measures() {
  using K = FieldKind;
  static const std::vector<Measure> t{
      member("scenario", K::text, "", "the scenario file the run came from", &O::scenario),
      member("converged", K::boolean, "", "every robot stable", &O::converged).in_runs(0),
      outcome(
          "sim_time", K::number, "s", "simulated time at the end",
          [](const O& o) { return json(o.sim_time.seconds()); },
          [](O& o, const nlohmann::json& j) {
            o.sim_time = SimTime::from_seconds(j.get<double>());
          })
          .in_runs(1)
          .in_summary(),
      outcome(
          "robots", K::json, "", "per robot, in scenario order (robot_fields)",
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
          }),
      member("cost.virtual", K::number, kCostUnit, "H of the virtual generators on their partition",
             &O::cost_virtual)
          .in_runs(2, "cost_virtual")
          .in_summary(),
      member("cost.real", K::number, kCostUnit, "H of the real positions on their partition",
             &O::cost_real)
          .in_runs(3, "cost_real")
          .in_summary(),
      member("cost.real_in_virtual_partition", K::number, kCostUnit,
             "H of the real positions on the virtual generators' partition",
             &O::cost_real_in_virtual_partition)
          .in_runs(4, "cost_real_in_virtual_partition")
          .in_summary(),
      outcome(
          "fingerprint", K::text, "", "16 hex digits",
          [](const O& o) { return json(Fingerprint::to_hex(o.fingerprint)); },
          [](O& o, const nlohmann::json& j) {
            o.fingerprint = std::stoull(j.get<std::string>(), nullptr, 16);
          })
          .in_runs(27),
      member("network.decentralized", K::boolean, "", "false for the ideal network (no messages)",
             &O::decentralized),
      messages("network.messages_sent", "link transmissions", &NetworkTotals::sent).in_runs(10),
      messages("network.messages_delivered", "messages delivered", &NetworkTotals::delivered)
          .in_runs(11)
          .in_summary(),
      messages("network.messages_lost",
               "messages lost by the loss model (a simulated radio: not received, those still "
               "on the air at the end included)",
               &NetworkTotals::lost)
          .in_runs(12)
          .in_summary(),
      messages("network.messages_unreachable", "messages out of range or blocked by walls",
               &NetworkTotals::unreachable)
          .in_runs(13)
          .in_summary(),
      outcome(
          "network.delivery_ratio", K::number, "", "messages delivered over link transmissions",
          [](const O& o) {
            return o.network.sent == 0 ? json(nullptr)
                                       : json(static_cast<double>(o.network.delivered) /
                                              static_cast<double>(o.network.sent));
          },
          [](O&, const nlohmann::json&) {})  // derived from the message counts
          .in_runs(28)
          .in_summary()
          .later(),
      latency("network.latency_mean", "mean time from a message's broadcast to its delivery",
              &NetworkTotals::latency_mean)
          .in_runs(29)
          .in_summary()
          .later(),
      latency("network.latency_p95", "95th percentile of that time (from a histogram: within 2.3%)",
              &NetworkTotals::latency_p95)
          .in_runs(30)
          .in_summary()
          .later(),
      radio("network.channel_occupancy", K::number,
            "simulated radio: mean fraction of the time a robot's radio found the air busy "
            "(sending, receiving or sensing energy)",
            &RadioTotals::occupancy)
          .in_runs(31)
          .in_summary()
          .later(),
      radio("network.phy_drops", K::integer,
            "simulated radio: receptions that began and failed (collisions and noise; ns-3's "
            "PHY drop trace)",
            &RadioTotals::phy_drops)
          .in_runs(32)
          .in_summary()
          .later(),
      radio("network.transmissions", K::integer, "simulated radio: frames put on the air",
            &RadioTotals::transmissions)
          .later(),
      radio("network.mac_drops", K::integer,
            "simulated radio: frames dropped before the air (MAC queue full or too old)",
            &RadioTotals::mac_drops)
          .later(),
      communication("info_age_mean", "s", "mean age of neighbour-table entries, over the samples",
                    &CommunicationSummary::info_age_mean)
          .in_runs(14)
          .in_summary(),
      communication("info_age_max", "s", "largest age of a neighbour-table entry",
                    &CommunicationSummary::info_age_max)
          .in_runs(15)
          .in_summary(),
      communication(
          "area_claimed_by_none", "m²",
          "mean area of Ω in no robot's own cell (cells from each robot's table), over the samples",
          &CommunicationSummary::area_claimed_by_none)
          .in_runs(16)
          .in_summary(),
      communication("area_claimed_by_several", "m²",
                    "mean area of Ω in two or more robots' own cells",
                    &CommunicationSummary::area_claimed_by_several)
          .in_runs(17)
          .in_summary(),
      communication("connected_fraction", "",
                    "fraction of the samples at which the communication graph was connected",
                    &CommunicationSummary::connected_fraction)
          .in_runs(18)
          .in_summary(),
      communication("algebraic_connectivity_min", "",
                    "least algebraic connectivity of the communication graph",
                    &CommunicationSummary::algebraic_connectivity_min)
          .in_runs(19)
          .in_summary(),
      member("convergence.time_to_10_percent", K::number, "s",
             "from when the real cost stays within 10% of its final value", &O::time_to_10_percent)
          .in_runs(6)
          .in_summary(),
      member("convergence.time_to_5_percent", K::number, "s", "the same within 5%",
             &O::time_to_5_percent)
          .in_runs(7)
          .in_summary(),
      member("convergence.time_to_1_percent", K::number, "s", "the same within 1%",
             &O::time_to_1_percent)
          .in_runs(8)
          .in_summary(),
      member("convergence.cost_to_best", K::number, "",
             "the final real cost over the least one sampled during the run (1: ended at its "
             "best)",
             &O::cost_to_best)
          .in_runs(9)
          .in_summary()
          .later(),
      member("convergence.path_length", K::number, "m", "all robots' paths", &O::path_length)
          .in_runs(5)
          .in_summary(),
      member("failures.target_outside_steps", K::integer, "",
             "loop-2 steps with the loop-1 target outside Ω, all robots", &O::target_outside_steps)
          .in_runs(22)
          .in_summary(),
      member("failures.stalled_time", K::number, "s", "time planners spent stalled",
             &O::stalled_time)
          .in_runs(23)
          .in_summary(),
      member("failures.centroid_distance_mean", K::number, "m",
             "mean final distance from the cell's centroid", &O::centroid_distance_mean)
          .in_runs(24, "centroid_distance")
          .in_summary(),
      member("failures.centroid_distance_max", K::number, "m",
             "largest final distance from the cell's centroid", &O::centroid_distance_max),
      member("bodies.radius", K::number, "m", "the robots' radius (0: points)", &O::radius).later(),
      nullable(
          "bodies.gap_min", "m",
          "least distance between two robots' bodies at a motion step (negative: they overlapped; "
          "null for points)",
          &O::body_gap_min)
          .in_runs(33)
          .in_summary()
          .later(),
      member("bodies.contact_time", K::number, "s",
             "robot-seconds with a body overlapping another robot's", &O::contact_time)
          .in_runs(34)
          .in_summary()
          .later(),
      member("bodies.wall_contacts", K::integer, "",
             "motion steps that ended with a body overlapping a wall (0 with a radius: robots "
             "move in Ω shrunk by it)",
             &O::wall_contacts)
          .in_runs(35)
          .in_summary()
          .later(),
      member("bodies.deadlocks", K::integer, "",
             "times a robot was blocked by its neighbours, making good a tenth of its planner's "
             "step or less, for 1 s or longer (with collision avoidance)",
             &O::deadlocks)
          .in_runs(36)
          .in_summary()
          .later(),
      member("bodies.deadlock_time", K::number, "s", "robot-seconds those deadlocks lasted",
             &O::deadlock_time)
          .in_runs(37)
          .in_summary()
          .later(),
      member("bodies.deadlocks_resolved", K::integer, "",
             "deadlocks that ended, the robot reaching a planner step again, before the run did",
             &O::deadlocks_resolved)
          .later(),
      member("bodies.turn_time", K::number, "s",
             "robot-seconds spent turning in place (kinematics with a heading)", &O::turn_time)
          .in_runs(38)
          .in_summary()
          .later(),
      member("bodies.hard_stops", K::integer, "",
             "stops harder than the acceleration limit: a detour moved the point a body was "
             "driving to",
             &O::hard_stops)
          .later(),
      member("localization.error_mean", K::number, "m",
             "mean distance between a robot's estimate of its position and the position, over "
             "every robot's loop-2 steps (0 with exact localization)",
             &O::localization_error_mean)
          .in_runs(39, "localization_error")
          .in_summary()
          .later(),
      member("localization.error_max", K::number, "m",
             "largest distance between a robot's estimate and its position at a loop-2 step",
             &O::localization_error_max)
          .later(),
      member("localization.fixes", K::integer, "", "tracking fixes the robots received", &O::fixes)
          .later(),
      member("mapping.known", K::text, "",
             "what the robots knew of Ω beforehand: full, boundary or none (environment.known)",
             &O::known)
          .in_runs(40, "known")
          .later(),
      member("mapping.known_fraction", K::number, "",
             "fraction of Ω's free area known at the end, over every robot's map (1 when Ω was "
             "known)",
             &O::known_fraction)
          .in_runs(41, "known_fraction")
          .in_summary()
          .later(),
      member("mapping.known_fraction_min", K::number, "",
             "the least fraction of Ω's free area one robot's map held at the end",
             &O::known_fraction_min)
          .later(),
      nullable(
          "mapping.time_to_90_percent", "s",
          "when the robots' maps together first held 90% of Ω's free area (0 when Ω was known; "
          "null: never)",
          &O::mapping_time_90)
          .in_runs(42, "mapping_time_90")
          .in_summary()
          .later(),
      nullable("mapping.time_to_100_percent", "s",
               "when they first held all of it, to the lattice's cells (null: never)",
               &O::mapping_time_100)
          .later(),
      member("mapping.disagreement", K::number, "",
             "mean over the robots of the fraction of Ω's free area some robot knew and it did "
             "not, at the end (0 with one shared map)",
             &O::map_disagreement)
          .in_runs(43, "map_disagreement")
          .in_summary()
          .later(),
      member("mapping.bytes", K::integer, "bytes",
             "map bytes broadcast (each broadcast once, whatever its receivers)", &O::map_bytes)
          .in_runs(44, "map_bytes")
          .in_summary()
          .later(),
      member("mapping.bytes_new", K::integer, "bytes",
             "of those, readings a robot sent for the first time (the rest repeat older ones in "
             "the spare room of a broadcast)",
             &O::map_bytes_new)
          .later(),
      member("mapping.scans", K::integer, "", "range readings kept for the maps", &O::scans)
          .later(),
      member("mapping.obstacles", K::integer, "",
             "obstacles to find: holes, and with known none the pockets of the outer ring",
             &O::obstacles)
          .later(),
      member("mapping.obstacles_known_min", K::integer, "",
             "how many of them the least-informed robot knew whole at the end",
             &O::obstacles_known_min)
          .later(),
      member("mapping.discoveries", K::integer, "",
             "times a robot's planner found a goal unreachable that its map placed in free space "
             "(an obstacle not yet known whole: the paper's Fig. 4 without a map)",
             &O::discoveries)
          .later(),
      member(
          "mapping.model", K::text, "",
          "the robots' map: polygons (the obstacles whose walls exact readings showed) or "
          "occupancy (a log-odds occupancy grid, for uncertain readings; empty when Ω was known)",
          &O::map_model)
          .later(),
      nullable("mapping.false_occupied", "",
               "with the occupancy grid, the mean over the robots' maps of the fraction of the "
               "cells wholly in Ω held occupied at the end (null with polygons)",
               &O::map_false_occupied)
          .later(),
      nullable("mapping.false_free", "",
               "with the occupancy grid, the mean over the robots' maps of the fraction of the "
               "cells wholly outside Ω held free at the end (null with polygons)",
               &O::map_false_free)
          .later(),
      nullable(
          "mapping.cost_known", kCostUnit,
          "H of the real positions at the end of the same run with Ω known (mapping.compare_known; "
          "null: not run)",
          &O::cost_known)
          .later(),
      outcome(
          "mapping.cost_ratio", K::number, "",
          "final real cost over mapping.cost_known (null: not compared)",
          [](const O& o) { return number_or_null(o.cost_ratio()); },
          [](O&, const nlohmann::json&) {})
          .in_runs(45, "cost_ratio")
          .in_summary()
          .later(),
      nullable("loops.ratio", "",
               "the Lloyd/planner frequency ratio, loops.loop1_period / loops.loop2_period "
               "(null: the classic schedule, loop 1 when a robot has settled)",
               &O::loop_ratio)
          .in_runs(46, "loop_ratio")
          .in_summary()
          .later(),
      member("planner.steps", K::integer, "", "planner steps taken", &O::planner_steps),
      outcome(
          "planner.step_time_us", K::number, "µs",
          "mean wall-clock time of a planner step (varies between runs)",
          [](const O& o) { return json(o.planner_step_time_us()); },
          [](O& o, const nlohmann::json& j) {
            o.planner_seconds = j.get<double>() * 1e-6 * static_cast<double>(o.planner_steps);
          })
          .in_runs(25, "planner_step_time")
          .in_summary(),
      member("stop_reason", K::text, "",
             "converged, planner_failure, left_environment, stuck or max_time", &O::stop_reason)
          .in_runs(21),
      incident("planner_failure",
               "null, or the robot, time, goal and position of a planner failure",
               &O::planner_failure),
      incident("left_environment",
               "null, or the robot, time, goal and crossing point of a robot that drove out of Ω",
               &O::left_environment)
          .later(),
      member("events", K::integer, "", "events dispatched", &O::events).in_runs(20),
      member("seed", K::integer, "", "the run's seed", &O::seed),
      outcome(
          "provenance", K::json, "",
          "what built covsim: version, commit, dirty, compiler, build_type, flags",
          [](const O& o) { return json(o.provenance); },
          [](O& o, const nlohmann::json& j) { o.provenance = j; }),
      of_run("wall_time", "s", "wall-clock time of the run",
             [](const RunMeasures& r) { return json(r.wall_time); })
          .in_runs(26)
          .in_summary(),
  };
  return t;
}

}  // namespace covsim
