#include "analysis/final_json.hpp"

#include <nlohmann/json.hpp>

#include "core/fingerprint.hpp"

namespace covsim {

std::string final_json(const CoverageOutcome& o) {
  nlohmann::ordered_json j;
  j["scenario"] = o.scenario;
  j["converged"] = o.converged;
  j["sim_time"] = o.sim_time.seconds();
  j["robots"] = nlohmann::ordered_json::array();
  for (const RobotOutcome& r : o.robots) {
    nlohmann::ordered_json robot;
    robot["position"] = {r.position.x, r.position.y};
    robot["virtual_generator"] = {r.virtual_generator.x, r.virtual_generator.y};
    robot["virtual_target"] = {r.virtual_target.x, r.virtual_target.y};
    robot["real_target"] = {r.real_target.x, r.real_target.y};
    robot["projected"] = r.projected;
    robot["status"] = std::string(to_string(r.status));
    robot["path_length"] = r.path_length;
    robot["target_outside_steps"] = r.target_outside_steps;
    robot["stalled_time"] = r.stalled_time;
    robot["centroid_distance"] = r.centroid_distance;
    j["robots"].push_back(std::move(robot));
  }
  j["cost"] = {{"virtual", o.cost_virtual},
               {"real", o.cost_real},
               {"real_in_virtual_partition", o.cost_real_in_virtual_partition}};
  j["fingerprint"] = Fingerprint::to_hex(o.fingerprint);
  nlohmann::ordered_json net;
  net["decentralized"] = o.decentralized;
  net["messages_sent"] = o.network.sent;
  net["messages_delivered"] = o.network.delivered;
  net["messages_lost"] = o.network.lost;
  net["messages_unreachable"] = o.network.unreachable;
  j["network"] = std::move(net);
  nlohmann::ordered_json conv;
  conv["time_to_10_percent"] = o.time_to_10_percent;
  conv["time_to_5_percent"] = o.time_to_5_percent;
  conv["time_to_1_percent"] = o.time_to_1_percent;
  conv["path_length"] = o.path_length;
  j["convergence"] = std::move(conv);
  nlohmann::ordered_json fail;
  fail["target_outside_steps"] = o.target_outside_steps;
  fail["stalled_time"] = o.stalled_time;
  fail["centroid_distance_mean"] = o.centroid_distance_mean;
  fail["centroid_distance_max"] = o.centroid_distance_max;
  j["failures"] = std::move(fail);
  nlohmann::ordered_json planner;
  planner["steps"] = o.planner_steps;
  planner["step_time_us"] = o.planner_step_time_us();
  j["planner"] = std::move(planner);
  j["stop_reason"] = o.stop_reason;
  if (o.planner_failure) {
    const PlannerFailure& f = *o.planner_failure;
    j["planner_failure"] = {{"robot", f.robot},
                            {"time", f.time.seconds()},
                            {"goal", {f.goal.x, f.goal.y}},
                            {"position", {f.position.x, f.position.y}}};
  } else {
    j["planner_failure"] = nullptr;
  }
  j["events"] = o.events;
  j["seed"] = o.seed;
  return j.dump(2) + "\n";
}

}  // namespace covsim
