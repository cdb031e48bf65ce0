#include "analysis/records/result_fields.hpp"

#include <algorithm>
#include <stdexcept>

#include "analysis/records/json_point.hpp"

namespace covsim {

namespace {
using json = nlohmann::ordered_json;
}  // namespace

const FieldTable<CoverageOutcome>& final_fields() {
  static const FieldTable<CoverageOutcome> t = [] {
    FieldTable<CoverageOutcome> out;
    for (const Measure& m : measures()) {
      if (m.in_final())
        out.push_back({m.name, m.kind, m.unit, m.description, m.of_outcome, m.set, m.summarized,
                       m.added_later});
    }
    return out;
  }();
  return t;
}

const FieldTable<RunMeasures>& run_fields() {
  static const FieldTable<RunMeasures> t = [] {
    std::vector<const Measure*> in_runs;
    for (const Measure& m : measures()) {
      if (m.run_place) in_runs.push_back(&m);
    }
    std::sort(in_runs.begin(), in_runs.end(),
              [](const Measure* a, const Measure* b) { return *a->run_place < *b->run_place; });
    FieldTable<RunMeasures> out;
    for (const Measure* m : in_runs) {
      // Places 0 to N-1, each once: a gap or a repeat would leave runs.csv's order to chance.
      if (*m->run_place != static_cast<int>(out.size()))
        throw std::logic_error("measure " + m->name + ": runs.csv place " +
                               std::to_string(*m->run_place) + ", expected " +
                               std::to_string(out.size()));
      out.push_back({m->column(), m->kind, m->unit, m->description,
                     [m](const RunMeasures& r) { return m->of(r); }, nullptr, m->summarized,
                     m->added_later});
    }
    return out;
  }();
  return t;
}

const FieldTable<RobotOutcome>& robot_fields() {
  using R = RobotOutcome;
  using K = FieldKind;
  const auto at = [](std::string name, std::string description, Vec2 R::*m) {
    return Field<R>{std::move(name),
                    K::point,
                    "m",
                    std::move(description),
                    [m](const R& r) { return point_json(r.*m); },
                    [m](R& r, const nlohmann::json& j) { r.*m = json_point(j); }};
  };
  static const FieldTable<R> t{
      at("position", "where the robot ended (its real generator)", &R::position),
      at("virtual_generator", "its virtual generator", &R::virtual_generator),
      at("virtual_target", "its last loop-1 target", &R::virtual_target),
      at("real_target", "the virtual target, or its projection onto Ω", &R::real_target),
      member_field("projected", K::boolean, "", "the virtual target lies outside Ω", &R::projected),
      Field<R>{
          "status", K::text, "", "the planner's: " + plan_status_names(),
          [](const R& r) { return json(std::string(to_string(r.status))); },
          [](R& r, const nlohmann::json& j) { r.status = status_named(j.get<std::string>()); }},
      member_field("path_length", K::number, "m", "distance travelled", &R::path_length),
      member_field("target_outside_steps", K::integer, "",
                   "loop-2 steps taken while its loop-1 target lay outside Ω",
                   &R::target_outside_steps),
      member_field("stalled_time", K::number, "s", "time its planner spent stalled",
                   &R::stalled_time),
      member_field("centroid_distance", K::number, "m",
                   "final distance from the centroid of its cell in the last partition",
                   &R::centroid_distance),
  };
  return t;
}

const FieldTable<MetricsSample>& metrics_fields() {
  using S = MetricsSample;
  using K = FieldKind;
  const auto get = [](std::string name, K kind, std::string unit, std::string description,
                      std::function<json(const S&)> g) {
    return Field<S>{std::move(name),        kind,         std::move(unit),
                    std::move(description), std::move(g), nullptr};
  };
  static const FieldTable<S> t{
      member_field("t", K::number, "s", "sample time", &S::t),
      member_field("cost_real", K::number, kCostUnit, "H of the real positions", &S::cost_real),
      member_field("cost_virtual", K::number, kCostUnit, "H of the virtual generators",
                   &S::cost_virtual),
      member_field("cost_real_in_virtual_partition", K::number, kCostUnit,
                   "H of the real positions on the virtual partition",
                   &S::cost_real_in_virtual_partition),
      member_field("settled", K::integer, "", "robots whose planner has settled", &S::settled),
      member_field("projected", K::integer, "", "robots whose virtual target lies outside Ω",
                   &S::projected),
      member_field("path_length", K::number, "m", "distance travelled by all robots",
                   &S::path_length),
      get("messages_sent", K::integer, "", "link transmissions so far",
          [](const S& s) { return json(s.messages.sent); }),
      get("messages_delivered", K::integer, "", "messages delivered so far",
          [](const S& s) { return json(s.messages.delivered); }),
      get("messages_lost", K::integer, "", "messages lost so far",
          [](const S& s) { return json(s.messages.lost); }),
      get("info_age_mean", K::number, "s", "mean age of neighbour-table entries",
          [](const S& s) { return json(s.network.info_age_mean); }),
      get("info_age_max", K::number, "s", "largest age of a neighbour-table entry",
          [](const S& s) { return json(s.network.info_age_max); }),
      get("area_claimed_by_none", K::number, "m²", "area of Ω in no robot's own cell",
          [](const S& s) { return json(s.network.area_claimed_by_none); }),
      get("area_claimed_by_several", K::number, "m²", "area of Ω in two or more robots' own cells",
          [](const S& s) { return json(s.network.area_claimed_by_several); }),
      get("components", K::integer, "", "connected components of the communication graph",
          [](const S& s) { return json(s.network.graph.components); }),
      get("largest_component", K::integer, "", "robots in the largest component",
          [](const S& s) { return json(s.network.graph.largest_component); }),
      get("diameter_hops", K::integer, "", "largest hop distance between reachable robots",
          [](const S& s) { return json(s.network.graph.diameter); }),
      get("average_degree", K::number, "", "mean number of neighbours",
          [](const S& s) { return json(s.network.graph.average_degree); }),
      get("algebraic_connectivity", K::number, "",
          "second-smallest eigenvalue of the graph Laplacian",
          [](const S& s) { return number_or_null(s.network.graph.algebraic_connectivity); }),
      // Read back by nothing (the figures need the costs only): no setter, as above.
      get("known_fraction", K::number, "",
          "fraction of Ω's free area the robots' maps together hold (1: Ω known)",
          [](const S& s) { return json(s.known_fraction); }),
      get("known_fraction_min", K::number, "", "the least fraction one robot's own map holds",
          [](const S& s) { return json(s.known_fraction_min); }),
      get("map_disagreement", K::number, "",
          "mean over the robots of the fraction some robot's map holds and its own not",
          [](const S& s) { return json(s.map_disagreement); }),
  };
  return t;
}

}  // namespace covsim
