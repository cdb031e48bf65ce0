#include "robot/mapping.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/geometry_error.hpp"

namespace covsim {

Mapping::Mapping(const Environment& env, const Density& density, double radius, double range,
                 const MappingConfig& config, std::size_t robots, bool shared)
    : env_(env),
      density_(density),
      radius_(radius),
      range_(range),
      config_(config),
      elements_(map_elements(env, config.known == KnownEnvironment::none)),
      travelled_(robots, 0.0),
      free_cells_(KnownLattice::of_free_space(env, static_cast<std::uint32_t>(config.cells))),
      merged_(env.bounds(), static_cast<std::uint32_t>(config.cells)) {
  free_count_ = free_cells_.count();
  merged_time_.assign(
      static_cast<std::size_t>(merged_.nx()) * static_cast<std::size_t>(merged_.ny()), NAN);
  // With the outer ring known (boundary), its pockets are not elements: only holes are.
  const std::vector<bool> known(elements_.size(), false);
  const std::shared_ptr<const Belief> prior = belief_for(known);
  const std::size_t maps = shared ? 1 : robots;
  for (std::size_t m = 0; m < maps; ++m) {
    RobotMap map(SeenWalls(env), known, prior);
    // One shared map holds every reading: the merged lattice is its lattice.
    if (maps > 1)
      map.lattice = KnownLattice(env.bounds(), static_cast<std::uint32_t>(config.cells));
    maps_.push_back(std::move(map));
  }
  if (config.robot_maps && maps > 1)
    robot_time_.assign(maps, std::vector<double>(merged_time_.size(), NAN));
}

Mapping::~Mapping() = default;

void Mapping::use_grid(double noise, std::vector<RandomStream> streams,
                       std::function<Vec2(std::uint32_t)> offset,
                       std::function<Vec2(std::uint32_t)> believed) {
  grid_ = true;
  noise_ = noise;
  noise_rng_ = std::move(streams);
  offset_ = std::move(offset);
  believed_ = std::move(believed);
  const double h = merged_.cell();
  const std::size_t n =
      static_cast<std::size_t>(merged_.nx()) * static_cast<std::size_t>(merged_.ny());
  prior_open_.assign(n, 1);
  truth_.assign(n, 0);
  // With the outline known, Ω̂ keeps to the cells whose centre lies in it.
  std::unique_ptr<Environment> outline;
  if (config_.known == KnownEnvironment::boundary)
    outline = std::make_unique<Environment>(env_.outer(), std::vector<std::vector<Vec2>>{});
  for (std::int32_t j = 0; j < merged_.ny(); ++j)
    for (std::int32_t i = 0; i < merged_.nx(); ++i) {
      const Vec2 c = merged_.centre(i, j);
      const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(merged_.nx()) +
                            static_cast<std::size_t>(i);
      if (outline && !outline->contains(c)) prior_open_[k] = 0;
      // A cell's closed square lies within h/√2 of its centre (a wall through a corner
      // meets it).
      if (env_.boundary_distance(c) > h * std::sqrt(0.5) * (1.0 + 1e-9)) {
        truth_[k] = env_.contains(c) ? 1 : 2;
        ++(truth_[k] == 1 ? truth_in_ : truth_out_);
      }
    }
  for (RobotMap& m : maps_)
    m.cells = std::make_unique<LogOddsGrid>(merged_, config_.p_hit, config_.p_miss);
}

const Belief& Mapping::belief(std::uint32_t i) const {
  if (grid_) return grid_belief(map_of(i));
  // Built when asked for: the obstacles a robot's first readings close, one after another,
  // make one belief, not one each.
  const RobotMap& m = maps_[map_of(i)];
  if (!m.belief || m.belief_known != m.known) {
    m.belief = belief_for(m.known);
    m.belief_known = m.known;
  }
  return *m.belief;
}

const KnownLattice& Mapping::lattice(std::uint32_t i) const {
  // One map holds every reading: the merged lattice. Otherwise a robot's lattice is marked
  // when asked for (the measures at the end), not at each reading it hears.
  if (maps_.size() == 1) return merged_;
  const RobotMap& m = maps_[i];
  for (; m.filled < m.order.size(); ++m.filled)
    m.lattice.mark(runs_[m.order[m.filled]]);
  return m.lattice;
}

std::shared_ptr<const Belief> Mapping::belief_for(const std::vector<bool>& known) const {
  auto it = beliefs_.find(known);
  if (it != beliefs_.end()) return it->second;
  auto b = std::make_shared<Belief>();
  b->environment = believed_environment(env_, elements_, known);
  b->integrator = std::make_unique<CellIntegrator>(*b->environment, density_);
  b->space = std::make_unique<ConfigurationSpace>(*b->environment, radius_);
  return beliefs_.emplace(known, std::move(b)).first->second;
}

std::shared_ptr<const Belief> Mapping::grid_belief_of(
    const CellGrid& grid, const std::vector<std::uint8_t>& region) const {
  auto b = std::make_shared<Belief>();
  b->environment = region_environment(grid, region);
  b->integrator = std::make_unique<CellIntegrator>(*b->environment, density_);
  // Shrunk by the radius on the cells themselves: an offset of a staircase outline is many
  // coincident events for a straight skeleton (one crashed, dead_ends with 2 cm tracking).
  b->space = radius_ > 0.0 ? std::make_unique<ConfigurationSpace>(
                                 *b->environment, radius_, eroded_parts(grid, region, radius_))
                           : std::make_unique<ConfigurationSpace>(*b->environment, 0.0);
  return b;
}

const Belief& Mapping::grid_belief(std::size_t index) const {
  const RobotMap& m = maps_[index];
  const CellGrid& g = m.cells->grid();
  // Seeded where the robots holding the map believe they stand.
  std::vector<Vec2> seeds;
  std::vector<std::uint32_t> seed_cells;
  for (std::uint32_t i = 0; i < travelled_.size(); ++i) {
    if (map_of(i) != index) continue;
    seeds.push_back(believed_(i));
    seed_cells.push_back(g.cell_of(seeds.back()));
  }
  if (m.belief && m.region_version == m.cells->version() && m.seed_cells == seed_cells)
    return *m.belief;
  m.region_version = m.cells->version();
  m.seed_cells = seed_cells;
  std::vector<std::uint8_t> open(g.size());
  for (std::size_t c = 0; c < g.size(); ++c)
    open[c] = prior_open_[c] != 0 && !m.cells->occupied(c) ? 1 : 0;
  std::vector<std::uint8_t> region = seeded_region(g, open, seeds);
  if (region == m.region && m.belief) return *m.belief;
  try {
    m.belief = grid_belief_of(g, region);
    m.region = std::move(region);
  } catch (const std::invalid_argument&) {
    // No region, or one that leaves the robots' bodies no room: the last belief stands.
    if (!m.belief) throw;
  }
  return *m.belief;
}

const Environment& Mapping::free_space(std::uint32_t i, Vec2 p) const {
  const ConfigurationSpace& space = *belief(i).space;
  if (const auto k = space.part_of(p)) return space.part(*k);
  // Ω̂ ⊖ r holds Ω ⊖ r, so p lies in a part but for rounding: the nearest.
  std::size_t best = 0;
  double least = INFINITY;
  for (std::size_t k = 0; k < space.part_count(); ++k) {
    const double d = distance(p, space.part(k).closest_point(p));
    if (d < least) {
      least = d;
      best = k;
    }
  }
  return space.part(best);
}

void Mapping::start(std::uint32_t i, Vec2 p, SimTime t) {
  take(i, p, t);
}

void Mapping::moved(std::uint32_t i, Vec2 p, double length, SimTime t) {
  travelled_[i] += length;
  if (travelled_[i] >= config_.spacing) take(i, p, t);
}

void Mapping::settled(std::uint32_t i, Vec2 p, SimTime t) {
  if (travelled_[i] > 0.0) take(i, p, t);
}

void Mapping::take(std::uint32_t i, Vec2 p, SimTime t) {
  travelled_[i] = 0.0;
  // A reading larger than a message is kept as parts that each fit one.
  const auto limit = static_cast<std::uint32_t>(config_.max_bytes);
  if (!grid_) {
    for (Scan& part : split_scan(env_, take_scan(env_, p, range_), limit))
      record(i, std::move(part), GridPatch{}, t);
  } else {
    Scan scan = take_scan(env_, p, range_);
    add_range_noise(scan, noise_rng_[i], noise_, env_.tolerance());
    shift(scan, offset_(i));
    std::vector<GridPatch> parts = split_patch(inverse_sensor_model(merged_, scan), limit);
    for (std::size_t k = 0; k < parts.size(); ++k) {
      // The reading's walls and fan go with its first part.
      Scan part;
      if (k == 0) part = scan;
      part.origin = scan.origin;
      part.range = scan.range;
      record(i, std::move(part), std::move(parts[k]), t);
    }
  }
  note_merged(t);
}

void Mapping::record(std::uint32_t i, Scan scan, GridPatch patch, SimTime t) {
  const auto s = static_cast<std::uint32_t>(scans_.size());
  runs_.push_back(merged_.runs(scan.fan));
  fresh_.clear();
  merged_.mark(runs_.back(), &fresh_);
  for (const std::size_t k : fresh_)
    merged_time_[k] = t.seconds();
  scans_.push_back(std::move(scan));
  if (grid_) patches_.push_back(std::move(patch));
  add(map_of(i), s, t);
}

bool Mapping::add(std::size_t index, std::uint32_t s, SimTime t) {
  RobotMap& m = maps_[index];
  if (m.holds.size() <= s) m.holds.resize(scans_.size(), false);
  if (m.holds[s]) return false;
  m.holds[s] = true;
  m.order.push_back(s);
  const Scan& scan = scans_[s];
  if (!robot_time_.empty()) {
    // Each robot's own map's times: its lattice marked as it comes to hold readings.
    fresh_.clear();
    m.lattice.mark(runs_[s], &fresh_);
    for (const std::size_t k : fresh_)
      robot_time_[index][k] = t.seconds();
    m.filled = m.order.size();
  }
  if (grid_) m.cells->apply(patches_[s]);
  // An obstacle is known once its last wall is seen (the belief follows in belief(); with the
  // occupancy grid, a measure only).
  if (!m.walls.add(scan)) return true;
  for (std::size_t e = 0; e < elements_.size(); ++e)
    if (!m.known[e] && m.walls.seen(elements_[e])) m.known[e] = true;
  return true;
}

void Mapping::note_merged(SimTime t) {
  const double f = known_fraction();
  if (!time_90_ && f >= 0.9) time_90_ = t;
  if (!time_100_ && f >= 1.0) time_100_ = t;
}

MapPayload Mapping::pack(std::uint32_t sender) {
  RobotMap& m = maps_[map_of(sender)];
  auto ids = std::make_shared<std::vector<std::uint32_t>>();
  std::uint64_t bytes = 0;
  const auto fits = [&](std::uint32_t s) { return bytes + bytes_of(s) <= config_.max_bytes; };
  // Those not yet sent first, in the order it came to hold them.
  while (m.sent < m.order.size() && fits(m.order[m.sent])) {
    ids->push_back(m.order[m.sent]);
    bytes += bytes_of(m.order[m.sent]);
    ++m.sent;
  }
  new_bytes_sent_ += bytes;
  // Room left: older ones again, in turn (a receiver may have lost them).
  const std::size_t older = m.sent - ids->size();
  for (std::size_t k = 0; k < older; ++k) {
    if (m.repeat >= older) m.repeat = 0;
    const std::uint32_t s = m.order[m.repeat];
    if (!fits(s)) break;
    ids->push_back(s);
    bytes += bytes_of(s);
    ++m.repeat;
  }
  bytes_sent_ += bytes;
  return MapPayload{std::move(ids), static_cast<std::uint32_t>(bytes)};
}

void Mapping::merge(std::uint32_t receiver, const MapPayload& payload) {
  if (!payload.scans) return;
  const SimTime t = now_ ? now_() : SimTime::zero();
  for (const std::uint32_t s : *payload.scans)
    // A planner takes the walls of exact readings only (a noisy neighbour's walls, placed by
    // its estimate, are not its own robot's).
    if (add(map_of(receiver), s, t) && learned_ && !grid_) learned_(receiver, scans_[s]);
}

double Mapping::known_fraction() const {
  return free_count_ == 0
             ? 1.0
             : static_cast<double>(merged_.common(free_cells_)) / static_cast<double>(free_count_);
}

double Mapping::known_fraction(std::uint32_t i) const {
  return free_count_ == 0 ? 1.0
                          : static_cast<double>(lattice(i).common(free_cells_)) /
                                static_cast<double>(free_count_);
}

double Mapping::disagreement() const {
  if (maps_.size() <= 1 || free_count_ == 0) return 0.0;
  const double merged = static_cast<double>(merged_.common(free_cells_));
  double sum = 0.0;
  for (std::uint32_t i = 0; i < maps_.size(); ++i)
    sum += merged - static_cast<double>(lattice(i).common(free_cells_));
  return sum / static_cast<double>(maps_.size()) / static_cast<double>(free_count_);
}

std::size_t Mapping::elements_known_min() const {
  std::size_t least = elements_.size();
  for (const RobotMap& m : maps_)
    least = std::min<std::size_t>(
        least, static_cast<std::size_t>(std::count(m.known.begin(), m.known.end(), true)));
  return least;
}

Mapping::MapErrors Mapping::errors() const {
  MapErrors out;
  if (!grid_) return out;
  for (const RobotMap& m : maps_) {
    std::size_t occupied = 0, free = 0;
    for (std::size_t c = 0; c < truth_.size(); ++c) {
      if (truth_[c] == 1 && m.cells->occupied(c)) ++occupied;
      if (truth_[c] == 2 && m.cells->observed(c) && !m.cells->occupied(c)) ++free;
    }
    if (truth_in_ > 0)
      out.false_occupied += static_cast<double>(occupied) / static_cast<double>(truth_in_);
    if (truth_out_ > 0)
      out.false_free += static_cast<double>(free) / static_cast<double>(truth_out_);
  }
  out.false_occupied /= static_cast<double>(maps_.size());
  out.false_free /= static_cast<double>(maps_.size());
  return out;
}

}  // namespace covsim
