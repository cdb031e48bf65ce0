#include "planners/sensed_map_planner.hpp"

#include <algorithm>

namespace covsim {

std::shared_ptr<SensedMap> sensed_map_for(const Environment& env, double resolution,
                                          const SensorSpec& sensor) {
  // Cells aligned with the given map's occupancy grid (from the corner of the same box), so
  // that a wall cell here is a blocked cell there: where the given grid joins two cells, so
  // does the sensed one.
  return std::make_shared<SensedMap>(env.bounds(), resolution, env.tolerance(), sensor.spread());
}

void SensedMapPlanner::set_goal(Vec2 goal) {
  goal_ = goal;
  planned_ = projecting_ = settling_ = escaping_ = false;
  escapes_ = 0;
  reroutes_ = 0;
  proposed_from_ = Vec2{INFINITY, INFINITY};
  slide_.reset();
  status_ = PlanStatus::moving;
  follower_.clear();
}

std::optional<std::vector<Vec2>> SensedMapPlanner::route(const SensedMap& m, Vec2 start,
                                                         Vec2 goal) {
  planning_ = &m;
  if (m.clear(start, goal)) return std::vector<Vec2>{start, goal};
  const auto from = m.entry(start);
  if (!from) return std::nullopt;
  if (const auto to = m.entry(goal))
    if (auto path = plan(start, *from, goal, *to)) return path;
  // Else the goal enters by a cell the start's reaches: the nearest free cell may lie beyond a
  // wall from it (the other side of a thin wall the goal lies on).
  const auto reach = m.reach(*from);
  const auto to = m.entry(goal, 4, &reach);
  if (!to) return std::nullopt;
  return plan(start, *from, goal, *to);
}

const SensedMap* SensedMapPlanner::finer_map() {
  if (!finer_ && !finer_tried_) {
    finer_tried_ = true;
    finer_ = map_->finer(kFiner, kMaxFinerCells);
    finer_synced_ = map_->added().size();
  }
  if (!finer_) return nullptr;
  const auto& added = map_->added();
  for (; finer_synced_ < added.size(); ++finer_synced_)
    finer_->add_wall(added[finer_synced_].a, added[finer_synced_].b);
  return finer_.get();
}

bool SensedMapPlanner::wall_nearer_than(const std::optional<SensedMap::Landing>& landing) const {
  const double at = landing ? distance(goal_, landing->point) : INFINITY;
  for (const SensedMap::Piece& p : map_->pieces())
    if (distance(goal_, project_to_segment(goal_, p.a, p.b).point) < at - tol_) return true;
  return false;
}

bool SensedMapPlanner::cut_off(const std::vector<std::uint8_t>& reach, Vec2 y) const {
  return !reach.empty() && !map_->entry(y, 4, &reach);
}

bool SensedMapPlanner::plan_on(const SensedMap& m, Vec2 x,
                               std::optional<SensedMap::Landing>& landing,
                               std::vector<std::uint8_t>& reach) {
  landing.reset();
  reach.clear();
  if (!projecting_) {
    if (auto path = route(m, x, goal_)) {
      follower_.assign(std::move(*path));
      arrival_ = PlanStatus::reached;
      return true;
    }
  }
  planning_ = &m;
  if (const auto from = m.entry(x)) {
    reach = m.reach(*from);
    landing = m.closest_reachable_wall(goal_, reach);
  }
  return false;
}

bool SensedMapPlanner::escape(Vec2 x) {
  // The free cell whose centre is nearest, within two rings, whatever the map says of the
  // way there, but for those tried from here already: the motion stops at a true wall.
  if (++escapes_ > kMaxEscapes) return false;
  if (escape_tried_.empty() || distance(x, escape_from_) > tol_) {
    escape_tried_.clear();
    escape_from_ = x;
  }
  const std::uint32_t c = map_->cell_of(x);
  std::optional<std::uint32_t> best;
  for (std::int32_t j = map_->row(c) - 2; j <= map_->row(c) + 2; ++j)
    for (std::int32_t i = map_->column(c) - 2; i <= map_->column(c) + 2; ++i) {
      const std::uint32_t k = map_->index(i, j);
      if (!map_->free(i, j) || distance(x, map_->center(k)) <= tol_ ||
          std::find(escape_tried_.begin(), escape_tried_.end(), k) != escape_tried_.end())
        continue;
      if (!best || distance(x, map_->center(k)) < distance(x, map_->center(*best))) best = k;
    }
  if (!best) return false;
  escape_tried_.push_back(*best);
  follower_.assign({x, map_->center(*best)});
  escaping_ = true;
  status_ = PlanStatus::moving;
  return true;
}

void SensedMapPlanner::replan(Vec2 x) {
  if (planned_) ++replans_;
  planned_ = true;
  escaping_ = false;
  // On a noisy map the robot may stand where no leg leaves by the map (noisy pieces of two
  // faces round a corner it stopped near): that says nothing of the goal. It first moves to
  // the nearest free cell.
  if (map_->spread() > 0.0 && !map_->entry(x) && escape(x)) return;
  std::optional<SensedMap::Landing> landing;
  std::vector<std::uint8_t> reach;  // the cells the robot's cell reaches on the map
  if (plan_on(*map_, x, landing, reach)) return;
  // (A noisy map's pieces lie off the walls: the robot settles by touch there instead.)
  const bool finer_possible = finer_ != nullptr || !finer_tried_;
  if (map_->spread() == 0.0 && finer_possible &&
      (wall_nearer_than(landing) || cut_off(reach, set_from_)))
    if (const SensedMap* finer = finer_map()) {
      std::optional<SensedMap::Landing> there;
      if (plan_on(*finer, x, there, reach)) return;
      if (there && (!landing || distance(goal_, there->point) < distance(goal_, landing->point)))
        landing = there;
      else
        planning_ = map_.get();
    }
  projecting_ = true;
  arrival_ = PlanStatus::projected;
  follower_.clear();
  status_ = PlanStatus::stalled;
  if (!landing) return;
  const SensedMap& m = *planning_;
  const auto from = m.entry(x);
  if (!from) return;
  landing_distance_ = distance(goal_, landing->point);
  landing_pieces_ = map_->added().size();
  auto path = m.clear(x, landing->point)
                  ? std::optional<std::vector<Vec2>>(std::vector<Vec2>{x, landing->point})
                  : plan(x, *from, landing->point, landing->cell);
  if (!path) return;
  follower_.assign(std::move(*path));
  status_ = PlanStatus::moving;
}

PlannerPicture SensedMapPlanner::picture() const {
  PlannerPicture out;
  out.map = map_.get();
  for (const SensedMap::Piece& p : map_->pieces())
    out.walls.emplace_back(p.a, p.b);
  // The way still ahead, from the waypoint it left last.
  const std::vector<Vec2>& path = follower_.path();
  const std::size_t from = follower_.next() == 0 ? 0 : follower_.next() - 1;
  if (status_ == PlanStatus::moving && from < path.size())
    out.path.assign(path.begin() + static_cast<std::ptrdiff_t>(from), path.end());
  return out;
}

bool SensedMapPlanner::nearer_wall() const {
  if (!projecting_) return false;
  const auto& pieces = map_->added();
  for (std::size_t k = landing_pieces_; k < pieces.size(); ++k)
    if (distance(goal_, project_to_segment(goal_, pieces[k].a, pieces[k].b).point) <
        landing_distance_)
      return true;
  return false;
}

bool SensedMapPlanner::ahead_clear(Vec2 x, std::size_t first_new) const {
  // Only a leg that passes near a new piece can have lost its way (a wall cell it meets lies
  // within a cell's diagonal of the piece).
  const std::vector<Vec2>& p = follower_.path();
  const auto& pieces = map_->added();
  const double near = 3.0 * map_->resolution();
  Vec2 from = x;
  for (std::size_t k = follower_.next(); k < p.size(); ++k) {
    bool touched = false;
    for (std::size_t n = first_new; n < pieces.size() && !touched; ++n)
      touched = segment_distance(from, p[k], pieces[n].a, pieces[n].b) <= near;
    if (touched && !planning_->clear(from, p[k])) return false;
    from = p[k];
  }
  return true;
}

void SensedMapPlanner::learn(const std::vector<SensedPiece>& walls) {
  for (const SensedPiece& w : walls)
    map_->add_wall(w.a, w.b);
}

PlanStep SensedMapPlanner::step(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  if (!planned_) set_from_ = x;
  map_->add(r);
  if (finer_) finer_map();
  // New walls, from this reading or (a shared map) another robot's since it last looked.
  const std::size_t first_new = seen_pieces_;
  const bool changed = map_->added().size() != first_new;
  seen_pieces_ = map_->added().size();
  // A touch superseded noisy pieces: a goal they cut off may be reachable after all.
  const bool lost = map_->supersessions() != seen_supersessions_;
  seen_supersessions_ = map_->supersessions();
  if (status_ != PlanStatus::moving) return PlanStep{x, status_};
  // Headed for a projection, or settling there: the walls lost may open a way to the goal.
  // (A bounded number of times per goal: a wall seen through noise now and then beside a
  // touched one is superseded again, and a goal outside Ω by less than the noise drew a
  // robot back and forth, traced on case 1944 at 2 m.)
  const bool reroute = lost && projecting_ && reroutes_ < kMaxReroutes;
  if (reroute) {
    ++reroutes_;
    projecting_ = settling_ = false;
    slide_.reset();
    replan(x);
  }
  if (settling_) return settle(r, max_step);
  // Walls only ever add (but for the noisy pieces a touch supersedes, above): a path still
  // clear stays the best the map allows, but for the way to a projection when a wall nearer
  // the goal came into view.
  // Stopped short of the path's end: by a wall it could not see (a contact sensor's).
  const bool ended = planned_ && follower_.done() && !follower_.path().empty();
  const double short_by = ended ? distance(x, follower_.path().back()) : INFINITY;
  const bool stopped = short_by > tol_ && ended;
  // Held where it stood by a wall it does not touch (a corner met within rounding): it
  // moves off to a free cell, or settles by touch if none is left to try.
  const bool held = map_->spread() > 0.0 && distance(x, proposed_from_) <= tol_;
  if (held && !escaping_) {
    if (!escape(x)) return start_settling(r, max_step);
    proposed_from_ = x;
    return PlanStep{follower_.advance(x, max_step, tol_), status_};
  }
  if (escaping_ && (ended || held)) {
    // Out, or held where it stood: plan again (another cell, if still no leg leaves).
    escaping_ = false;
    replan(x);
  } else if (reroute) {
    // Planned above.
  } else if (map_->spread() > 0.0 && short_by <= 2.0 * map_->merge() &&
             map_->clear(x, follower_.path().back())) {
    // On a noisy map the end may lie behind the wall that stopped the robot, within the noise.
    // (Unless the touch that stopped it shows the end behind that wall: it plans round.)
    return start_settling(r, max_step);
  } else if (!planned_ || stopped ||
             (map_->spread() == 0.0 && distance(x, proposed_from_) <= tol_) ||
             (changed && (nearer_wall() || !ahead_clear(x, first_new)))) {
    // Held where it stood on an exact map: moved off its path (a detour round a neighbour),
    // the rest of the path's leg from here meets a wall; a path from here does not.
    replan(x);
  }
  // A noisy map may show no way out of where the robot stands (walls seen a little too near,
  // round it): it settles by touch from there.
  if (status_ == PlanStatus::stalled && map_->spread() > 0.0) return start_settling(r, max_step);
  if (status_ != PlanStatus::moving) return PlanStep{x, status_};
  const Vec2 next = follower_.advance(x, max_step, tol_);
  // The end is claimed once the last step was seen clear, or taken; on a noisy map once the
  // robot stands there and settled by touch.
  if (follower_.done() && distance(x, next) <= std::max(r.range, tol_) && map_->spread() == 0.0)
    status_ = arrival_;
  proposed_from_ = distance(x, next) > tol_ ? x : Vec2{INFINITY, INFINITY};
  return PlanStep{next, status_};
}

PlanStep SensedMapPlanner::start_settling(const SensorReading& r, double max_step) {
  status_ = PlanStatus::moving;
  held_untouched_ = 0;
  settling_ = true;
  slide_.reset();
  tried_from_ = Vec2{INFINITY, INFINITY};
  return settle(r, max_step);
}

PlanStep SensedMapPlanner::settle(const SensorReading& r, double max_step) {
  const Vec2 x = r.position;
  const auto toward = [&](Vec2 p) {
    tried_from_ = x;
    const double d = distance(x, p);
    return PlanStep{d <= max_step ? p : x + (max_step / d) * (p - x), PlanStatus::moving};
  };
  if (distance(x, goal_) <= tol_) {
    status_ = PlanStatus::reached;
    return PlanStep{x, status_};
  }
  const bool held = distance(x, tried_from_) <= tol_;  // the last step did not move it
  if (slide_ && distance(x, *slide_) > tol_ && !held) return toward(*slide_);
  if (!slide_ && !held) return toward(goal_);
  // Stopped: straight for the goal again from the end of a slide; else to the point of the
  // walls it touches closest to the goal. (Stopped by no wall, a neighbour, say: again.)
  if (slide_ && !held) {
    slide_.reset();
    return toward(goal_);
  }
  const std::optional<Vec2> sliding = slide_;
  slide_.reset();
  std::optional<Vec2> closest;
  for (const ContactEdge& c : r.contacts) {
    const Vec2 q = project_to_segment(goal_, c.a, c.b).point;
    if (!closest || distance(goal_, q) < distance(goal_, *closest)) closest = q;
  }
  if (!closest) {
    // Held by nothing it touches, twice: it cannot tell where to go.
    if (held_untouched_++ > 0) {
      status_ = PlanStatus::stalled;
      return PlanStep{x, status_};
    }
    return toward(goal_);
  }
  held_untouched_ = 0;
  if (distance(x, *closest) <= tol_) {
    status_ = PlanStatus::projected;
    return PlanStep{x, status_};
  }
  if (sliding && distance(*sliding, *closest) <= tol_) {
    // Held on the way along the wall to the same point: it cannot get there.
    status_ = PlanStatus::stalled;
    return PlanStep{x, status_};
  }
  slide_ = closest;
  return toward(*closest);
}

}  // namespace covsim
