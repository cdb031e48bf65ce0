#pragma once
// Robots that do not know Ω (environment.known "boundary" or "none") map it as they cover.
//
// Each robot keeps range readings (scans, geometry/scan.hpp): one where it starts, one each
// time it has travelled mapping.spacing, one where it settles. From the walls they show it
// learns the obstacles whose every wall it has seen (geometry/map_elements.hpp); its belief Ω̂
// is the box or Ω's outer ring less those, so unknown space counts as free and Ω̂ ⊇ Ω. Loop 1
// computes cells and projections in Ω̂; a target in an obstacle not yet known is found
// unreachable by the planner (projection policy `discover`), which is the paper's Fig. 4. The
// free area the scans show is marked on a lattice (geometry/known_lattice.hpp) for the
// measures and figures.
//
// Centralized (the ideal network), the robots share one map. Decentralized, each robot has
// its own; every broadcast carries readings it holds (those not yet sent first, in the order
// it came to hold them, then older ones in turn, so that maps complete under loss) up to
// mapping.max_bytes, and a robot merges those it hears. Readings are kept run-wide once; a message
// carries their numbers and is counted at the size a robot would send them (Scan::bytes()).
//
// That map names the walls a reading saw, which only an exact reading can. With an uncertain
// reading (range noise, or a localization other than exact: mapping.model "auto") a robot maps
// on a log-odds occupancy grid (geometry/log_odds_grid.hpp) on the known-area lattice's
// cells: each reading, its ranges noisy and placed where the robot believes it stands, adds
// its hits and misses (geometry/grid_patch.hpp), and a message carries them as grid patches,
// counted at their size (GridPatch::bytes()). Ω̂ is then the cells not occupied that join the
// robots holding the map (unknown counts as free, as above; cells no robot can reach count as
// walls), the known part of Ω's outline taken as cells too (geometry/cell_region.hpp). A fix
// corrects where later readings are placed, not the readings placed before it: there is no
// loop closure, and the clamped log-odds let later readings outvote earlier misplaced ones.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "core/sim_time.hpp"
#include "geometry/cell_integrator.hpp"
#include "geometry/configuration_space.hpp"
#include "geometry/grid_patch.hpp"
#include "geometry/known_lattice.hpp"
#include "geometry/log_odds_grid.hpp"
#include "geometry/map_elements.hpp"
#include "robot/coverage_config.hpp"
#include "robot/map_exchange.hpp"

namespace covsim {

// Ω as a robot believes it, with what loop 1 computes in it.
struct Belief {
  std::unique_ptr<Environment> environment;
  std::unique_ptr<CellIntegrator> integrator;
  std::unique_ptr<ConfigurationSpace> space;  // Ω̂ shrunk by the robots' radius
};

class Mapping final : public MapExchange {
 public:
  // shared: one map for every robot (the centralized controller).
  Mapping(const Environment& env, const Density& density, double radius, double range,
          const MappingConfig& config, std::size_t robots, bool shared);

  // Readings are uncertain: the map is an occupancy grid. Robot i's readings get Gaussian
  // range noise of `noise` (m) from `streams[i]` and are placed `offset(i)` from where it
  // stands (its estimate less its position); `believed(i)` is where it believes it stands.
  void use_grid(double noise, std::vector<RandomStream> streams,
                std::function<Vec2(std::uint32_t)> offset,
                std::function<Vec2(std::uint32_t)> believed);
  bool grid() const { return grid_; }
  ~Mapping() override;

  // Robot i at p: its first reading (at the start).
  void start(std::uint32_t i, Vec2 p, SimTime t);
  // Robot i moved `length` to p: a reading once it has travelled mapping.spacing.
  void moved(std::uint32_t i, Vec2 p, double length, SimTime t);
  // Robot i settled at p: a reading there, unless it has not moved since its last.
  void settled(std::uint32_t i, Vec2 p, SimTime t);

  const Belief& belief(std::uint32_t i) const;
  // Where robot i, standing at p (in Ω shrunk by the radius), believes its centre may go.
  const Environment& free_space(std::uint32_t i, Vec2 p) const;

  MapPayload pack(std::uint32_t sender) override;
  void merge(std::uint32_t receiver, const MapPayload& payload) override;
  // The networked view merges at delivery; the time stamps the robots' own maps.
  void set_clock(std::function<SimTime()> now) { now_ = std::move(now); }
  // Called with each reading a robot merges from a neighbour's message that its map did not
  // hold (its map planner takes the walls too).
  void on_learn(std::function<void(std::uint32_t receiver, const Scan&)> f) {
    learned_ = std::move(f);
  }
  std::uint64_t payload_limit() const override { return config_.max_bytes; }

  // Measures, of the cells whose centre lies in Ω (KnownLattice::of_free_space).
  const std::vector<Scan>& scans() const { return scans_; }
  const KnownLattice& free_cells() const { return free_cells_; }
  const KnownLattice& merged() const { return merged_; }
  const KnownLattice& lattice(std::uint32_t i) const;
  // When cell (i, j) of the merged map became known (NaN: never).
  double known_since(std::int32_t i, std::int32_t j) const {
    return merged_time_[static_cast<std::size_t>(j) * static_cast<std::size_t>(merged_.nx()) +
                        static_cast<std::size_t>(i)];
  }
  // With mapping.robot_maps and a map per robot: when robot r's own map first held cell
  // (i, j) (NaN: never); empty otherwise.
  bool has_robot_times() const { return !robot_time_.empty(); }
  double known_since(std::uint32_t r, std::int32_t i, std::int32_t j) const {
    return robot_time_[r][static_cast<std::size_t>(j) * static_cast<std::size_t>(merged_.nx()) +
                          static_cast<std::size_t>(i)];
  }
  // The fraction of Ω's free area known: merged over the robots, and robot i's own.
  double known_fraction() const;
  double known_fraction(std::uint32_t i) const;
  // When the merged map first reached 90% and 100% of Ω's free area.
  std::optional<SimTime> time_to_90() const { return time_90_; }
  std::optional<SimTime> time_to_100() const { return time_100_; }
  // The mean over the robots of the fraction of Ω's free area some robot knows and it does
  // not (0 with one shared map).
  double disagreement() const;
  // Map bytes broadcast (each broadcast counted once, whatever its receivers).
  std::uint64_t bytes_sent() const { return bytes_sent_; }
  // Of those, the bytes of readings a robot sent for the first time (the rest repeat older
  // ones in spare room).
  std::uint64_t new_bytes_sent() const { return new_bytes_sent_; }
  // Obstacles (holes, and pockets of the outer ring with "none") and how many of them the
  // least-informed robot knows.
  std::size_t elements() const { return elements_.size(); }
  std::size_t elements_known_min() const;
  // With the occupancy grid: the mean over the robots' maps of the fraction of the cells
  // wholly in Ω held occupied, and of the cells wholly outside Ω held free (cells a wall
  // crosses are neither); 0 with the exact map.
  struct MapErrors {
    double false_occupied = 0.0, false_free = 0.0;
  };
  MapErrors errors() const;

 private:
  struct RobotMap {
    RobotMap(SeenWalls w, std::vector<bool> k, std::shared_ptr<const Belief> b)
        : walls(std::move(w)), known(std::move(k)), belief(std::move(b)) {}
    mutable KnownLattice lattice;  // order[0, filled) marked on it
    mutable std::size_t filled = 0;
    SeenWalls walls;
    std::vector<bool> known;                       // per element
    mutable std::shared_ptr<const Belief> belief;  // of belief_known (belief())
    mutable std::vector<bool> belief_known;
    std::vector<std::uint32_t> order;  // the readings it holds, as it came to hold them
    std::vector<bool> holds;           // per reading
    std::size_t sent = 0;              // order[0, sent) have been broadcast at least once
    std::size_t repeat = 0;            // the next of those to broadcast again
    // The occupancy grid, and the region of it last made Ω̂ (its version).
    std::unique_ptr<LogOddsGrid> cells;
    mutable std::vector<std::uint8_t> region;
    mutable std::uint64_t region_version = ~std::uint64_t{0};
    mutable std::vector<std::uint32_t> seed_cells;
  };
  std::size_t map_of(std::uint32_t i) const { return maps_.size() == 1 ? 0 : i; }
  void take(std::uint32_t i, Vec2 p, SimTime t);
  // Adds scan s to map m, updating its belief if an obstacle became known; whether m did not
  // hold it.
  bool add(std::size_t m, std::uint32_t s, SimTime t);
  std::shared_ptr<const Belief> belief_for(const std::vector<bool>& known) const;
  // Ω̂ of map m from its occupancy grid, rebuilt when the region it makes changed.
  const Belief& grid_belief(std::size_t m) const;
  // Ω̂ from a region of the grid's cells, shrunk by the radius on the cells.
  std::shared_ptr<const Belief> grid_belief_of(const CellGrid& grid,
                                               const std::vector<std::uint8_t>& region) const;
  // Where readings go: one (or its parts) of robot i at p.
  void record(std::uint32_t i, Scan scan, GridPatch patch, SimTime t);
  std::uint32_t bytes_of(std::uint32_t s) const {
    return grid_ ? patches_[s].bytes() : scans_[s].bytes();
  }
  void note_merged(SimTime t);

  const Environment& env_;
  const Density& density_;
  double radius_, range_;
  MappingConfig config_;
  std::vector<MapElement> elements_;
  std::vector<Scan> scans_;
  std::vector<std::vector<LatticeRun>> runs_;  // each reading's cells
  std::vector<RobotMap> maps_;
  std::vector<double> travelled_;  // per robot, since its last reading
  mutable std::map<std::vector<bool>, std::shared_ptr<const Belief>> beliefs_;
  KnownLattice free_cells_, merged_;
  std::vector<double> merged_time_;              // per cell, s
  std::vector<std::vector<double>> robot_time_;  // per robot map and cell, s (robot_maps)
  std::vector<std::size_t> fresh_;
  std::uint64_t free_count_ = 0;
  std::optional<SimTime> time_90_, time_100_;
  std::uint64_t bytes_sent_ = 0, new_bytes_sent_ = 0;
  std::function<SimTime()> now_;
  std::function<void(std::uint32_t, const Scan&)> learned_;
  // The occupancy grid's.
  bool grid_ = false;
  double noise_ = 0.0;
  std::vector<RandomStream> noise_rng_;
  std::function<Vec2(std::uint32_t)> offset_, believed_;
  std::vector<GridPatch> patches_;        // per reading (part)
  std::vector<std::uint8_t> prior_open_;  // cells Ω̂ may hold: in the known outline
  std::vector<std::uint8_t> truth_;       // per cell: 1 wholly in Ω, 2 wholly outside, 0 both
  std::size_t truth_in_ = 0, truth_out_ = 0;
};

}  // namespace covsim
