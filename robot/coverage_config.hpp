#pragma once
// Settings of the paper's coverage controller (Algorithms 1 and 2), with the defaults a
// scenario file gets when it leaves them out.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "core/config_key.hpp"
#include "core/sim_time.hpp"
#include "net/channel.hpp"
#include "planners/planner_entry.hpp"
#include "robot/collision_avoidance.hpp"
#include "robot/coverage_law.hpp"
#include "robot/kinematics.hpp"
#include "robot/localization.hpp"
#include "robot/sensor_model.hpp"

namespace covsim {

enum class LoopMode {
  classic,   // a robot runs loop 1 again once it has reached its real target (or settled)
  periodic,  // loop 1 runs every loop1_period, whatever the robots are doing
};

// Neighbour messages. With the ideal channel (the default) every robot knows every other
// robot's state at once, which is the centralized controller, and no message is simulated.
struct NetworkConfig {
  ChannelConfig channel;
  SimTime broadcast_period = SimTime::from_ns(100'000'000);  // 0.1 s
  // Each robot's first broadcast at a random offset within the period. Unset: not with the
  // abstract channel (the paper's synchronous rounds), but with a simulated radio, where
  // broadcasts at one instant would all collide (802.11 sends at once on an idle channel).
  std::optional<bool> random_phase;
  bool phases_random() const { return random_phase.value_or(channel.model != nullptr); }
  std::optional<SimTime> staleness;  // entries older than this are dropped; unset: never
  // Algorithm 1 acquires the neighbours (line 3) before its first Lloyd step: robots
  // broadcast from the start, and each runs its first loop 1 `acquire` later (unset: one
  // broadcast period). A robot that has heard nobody by then waits for its first message,
  // up to `acquire_timeout` after the start (unset: ten broadcast periods), then goes alone.
  std::optional<SimTime> acquire;
  std::optional<SimTime> acquire_timeout;
  SimTime acquire_time() const { return acquire.value_or(broadcast_period); }
  SimTime acquire_deadline() const {
    return acquire_timeout.value_or(SimTime::from_ns(10 * broadcast_period.ns()));
  }
};

// What the planner is told when a target lies outside Ω (Algorithm 2, lines 2-4).
enum class ProjectionPolicy {
  // The paper's Fig. 4: the planner is handed the virtual target and finds out that it is
  // unreachable (TangentBug walks round the obstacle), then settles at its projection. The
  // only choice when Ω is not known beforehand.
  discover,
  // Ω is known, so the controller's projection is the planner's goal from the start.
  known,
};
// The policies by their scenario names: the one list of them.
inline constexpr std::array<std::pair<ProjectionPolicy, std::string_view>, 2> kProjectionPolicies{
    {{ProjectionPolicy::discover, "discover"}, {ProjectionPolicy::known, "known"}}};
std::string_view to_string(ProjectionPolicy p);
std::optional<ProjectionPolicy> projection_named(std::string_view name);

// What the robots know of Ω beforehand (environment.known).
enum class KnownEnvironment {
  full,      // Ω itself: the paper's setting
  boundary,  // Ω's outer ring; its holes are found by sensing
  none,      // Ω's bounding box; the outer ring's pockets and the holes are found by sensing
};
inline constexpr std::array<std::pair<KnownEnvironment, std::string_view>, 3> kKnownEnvironments{
    {{KnownEnvironment::full, "full"},
     {KnownEnvironment::boundary, "boundary"},
     {KnownEnvironment::none, "none"}}};
std::string_view to_string(KnownEnvironment k);
std::optional<KnownEnvironment> known_environment_named(std::string_view name);

// How robots that do not know Ω map it (robot/mapping.hpp).
struct MappingConfig {
  KnownEnvironment known = KnownEnvironment::full;
  double spacing = 0.1;       // m travelled between range readings kept for the map
  double max_bytes = 1024;    // map bytes a broadcast carries at most
  double cells = 200;         // known-area lattice cells across Ω's box
  bool compare_known = true;  // also run with Ω known, for the cost ratio
  bool robot_maps = false;    // keep when each robot's own map held each cell
  // "auto": the exact map of walls seen when readings are exact, else an occupancy grid;
  // "polygons" or "occupancy" to choose.
  std::string model = "auto";
  double p_hit = 0.7, p_miss = 0.4;  // the occupancy grid's inverse sensor model
  bool unknown() const { return known != KnownEnvironment::full; }
  friend bool operator==(const MappingConfig&, const MappingConfig&) = default;
};

// Whether the robots' readings are uncertain (range noise, or a localization other than
// exact), and so whether a robot that maps Ω maps on an occupancy grid (mapping.model).
struct CoverageConfig;
bool readings_uncertain(const CoverageConfig& c);
bool maps_on_grid(const CoverageConfig& c);

// The robots' spacing: the side of a square of Ω's area shared out among n robots.
double robot_spacing(const Environment& env, std::size_t n);

struct CoverageConfig {
  LawConfig law;  // the scenario's "controller": which targets loop 1 hands the planners
  ProjectionPolicy projection = ProjectionPolicy::discover;
  LoopMode mode = LoopMode::classic;
  SimTime loop2_period = SimTime::from_ns(100'000'000);    // 0.1 s: one motion step
  SimTime loop1_period = SimTime::from_ns(1'000'000'000);  // periodic mode only
  // loops.ratio as given (loop1_period was set from it); unset otherwise.
  std::optional<double> loop_ratio;
  double max_speed = 0.1;  // m/s
  // Robots are disks of this radius (0: points): they plan and move in Ω ⊖ radius.
  double radius = 0.0;  // m
  // A map planner beside a localization plans on Ω shrunk by the radius plus this many
  // standard deviations of the estimate's error (a costmap's inflation).
  double inflation = 3.0;
  AvoidanceConfig avoidance;  // between bodies (radius > 0)
  KinematicsConfig kinematics;
  LocalizationConfig localization;  // what each robot knows of its own position
  SensorConfig sensor;
  PlannerConfig planner;
  // Convergence: every robot settled at its real target (within position_tolerance) and
  // every virtual generator within virtual_tolerance of its virtual target. Unset: the
  // fraction spacing_tolerance of the robots' spacing √(area of Ω / N), so that times compare
  // across scenarios and team sizes; without it, 1e-3 of the diameter of Ω's bounding box.
  std::optional<double> position_tolerance;
  std::optional<double> virtual_tolerance;
  std::optional<double> spacing_tolerance;
  double default_tolerance(double diameter, double spacing) const {
    return spacing_tolerance ? *spacing_tolerance * spacing : 1e-3 * diameter;
  }
  double position_tolerance_in(double diameter, double spacing) const {
    return position_tolerance.value_or(default_tolerance(diameter, spacing));
  }
  double virtual_tolerance_in(double diameter, double spacing) const {
    return virtual_tolerance.value_or(default_tolerance(diameter, spacing));
  }
  SimTime max_time = SimTime::from_ns(600'000'000'000);   // 600 s
  SimTime sample_period = SimTime::from_ns(500'000'000);  // metrics every 0.5 s
  // The most robots whose communication graph gets its algebraic connectivity at each
  // sample: above a few thousand its cost grows as about N^1.5, past the O(N log N) of the
  // rest of a sample.
  std::uint64_t algebraic_connectivity_robots = 2000;
  NetworkConfig network;
  MappingConfig mapping;
};

// The scenario's keys for these settings, each declared once with its schema (defaults
// from the structs above): "robots": {"max_speed"}, "controller": {"projection"}, "sensor",
// "loops", "convergence", "metrics", and the network's own keys.
ConfigKeys<CoverageConfig> motion_keys();
ConfigKeys<CoverageConfig> projection_keys();
ConfigKeys<CoverageConfig> sensor_keys();
ConfigKeys<CoverageConfig> loop_keys();
ConfigKeys<CoverageConfig> convergence_keys();
ConfigKeys<CoverageConfig> metrics_keys();
ConfigKeys<NetworkConfig> network_keys();
// "environment": {"known"}, and "mapping".
ConfigKeys<CoverageConfig> environment_keys();
ConfigKeys<CoverageConfig> mapping_keys();

}  // namespace covsim
