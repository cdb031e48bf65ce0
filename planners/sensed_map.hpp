#pragma once
// What one robot's map planner knows of Ω when it plans on what it has sensed
// (planner.map "sensed"): the walls its readings showed, and nothing else. Space it has not
// seen counts as free (the freespace assumption of Stentz's D* and of navigation costmaps),
// so a goal the map cannot reach is one Ω cannot reach either.
//
// The walls are kept twice: as pieces of the walls the sensor returned (free space on their
// left; a stretch that continues a piece along its wall extends it, so pieces stay few), for
// exact tests where a path starts or ends at a wall, and on a grid of square cells over
// the bounding box of the robot's free space, a cell being a wall cell when a piece touches
// its closed square. A leg of a path is clear when it crosses no piece and meets no wall cell
// farther than two cells from its ends: paths keep half a cell off what was seen, as on the
// given map's occupancy grid, and may still start and end on a wall.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/cell_walk.hpp"
#include "planners/grid_search.hpp"
#include "planners/sensor_reading.hpp"

namespace covsim {

class SensedMap {
 public:
  // Cells of side `resolution` over `bounds` grown by two cells (beyond them: walls).
  // `tolerance` is the geometry's; `spread` how far a sensed wall point may wander between
  // readings (range noise, a moving position estimate): a piece within max(tolerance, 3
  // spread) of the walls already held adds nothing.
  SensedMap(const Box& bounds, double resolution, double tolerance, double spread = 0.0);

  // The walls of a reading (its visible pieces, and of each wall it touches the stretch a
  // cell's side either way of the touch); whether it showed a wall the map did not hold (a
  // new piece, even within wall cells). A touch is exact, however noisy the ranges: a touched
  // stretch is new unless the walls held cover it to the tolerance.
  bool add(const SensorReading& reading);
  // One wall piece, free space on its left (a neighbour's, say), kept as the stretches of it
  // not held yet; whether there were any.
  bool add_wall(Vec2 a, Vec2 b);

  double resolution() const { return h_; }
  // The same walls on cells `factor` times finer; nullptr past `max_cells` cells. On an exact
  // map a finer grid closes fewer of the ways the pieces leave open.
  std::unique_ptr<SensedMap> finer(std::int32_t factor, double max_cells) const;
  // How far a sensed wall point may wander between readings (0 for exact readings).
  double spread() const { return spread_; }
  // Within this of a wall held, a wall seen is the same wall (and a point lies on it).
  double merge() const { return merge_; }
  std::int32_t nx() const { return nx_; }
  std::int32_t ny() const { return ny_; }
  std::size_t size() const { return wall_.size(); }
  GridShape shape() const { return GridShape{nx_, ny_, h_}; }
  // The cells reachable from cell `from` over the free ones (grid_reach), 1 where reachable.
  std::vector<std::uint8_t> reach(std::uint32_t from) const {
    return grid_reach(
        shape(), [this](std::int32_t i, std::int32_t j) { return free(i, j); }, from);
  }
  std::uint32_t index(std::int32_t i, std::int32_t j) const {
    return static_cast<std::uint32_t>(j * nx_ + i);
  }
  std::int32_t column(std::uint32_t c) const { return static_cast<std::int32_t>(c) % nx_; }
  std::int32_t row(std::uint32_t c) const { return static_cast<std::int32_t>(c) / nx_; }
  Vec2 center(std::uint32_t c) const;
  // The cell holding p (clamped to the grid).
  std::uint32_t cell_of(Vec2 p) const;
  bool free(std::int32_t i, std::int32_t j) const {
    return i >= 0 && j >= 0 && i < nx_ && j < ny_ && wall_[index(i, j)] == 0;
  }
  // The wall cells held now.
  std::size_t wall_cells() const { return wall_cells_; }
  // Changes whenever a cell becomes a wall cell or stops being one.
  std::size_t version() const { return version_; }
  // How many touches superseded noisy pieces (the map lost walls): a goal it had cut off may
  // be reachable again.
  std::size_t supersessions() const { return supersessions_; }

  struct Piece {
    Vec2 a, b;  // free space on the left of a -> b
    // Touched, so where the wall is (else within the noise of it).
    bool exact = true;
  };
  // The walls held, each a piece or a few along one wall (a stretch that continues a piece
  // extends it).
  const std::vector<Piece>& pieces() const { return pieces_; }
  // The stretches of wall the map gained, in order: what is new since one looked last.
  const std::vector<Piece>& added() const { return added_; }

  // Whether the leg p -> q is clear of what was sensed (above). At an end that lies on a
  // piece, the leg must leave into the free side.
  bool clear(Vec2 p, Vec2 q) const;
  // The free cell whose centre is nearest p among those p reaches by a clear leg, searching
  // `rings` rings of cells outward, and only among the cells `within` marks if given;
  // nullopt if none.
  std::optional<std::uint32_t> entry(Vec2 p, std::int32_t rings = 4,
                                     const std::vector<std::uint8_t>* within = nullptr) const;
  // The closest point to g on the pieces that a cell of `reachable` (indexed by cell) joins
  // by a clear leg, with that cell; nullopt if none. Where a goal no path reaches ends: the
  // walls that cut it off were sensed whole, so the closest of them is the projection.
  struct Landing {
    Vec2 point;
    std::uint32_t cell;
  };
  std::optional<Landing> closest_reachable_wall(Vec2 g,
                                                const std::vector<std::uint8_t>& reachable) const;

  // Calls f(i, j) for the cells a closed segment meets, in grid coordinates (outside the grid
  // included), until f returns false; whether it never did.
  template <class F>
  bool for_each_cell(Vec2 a, Vec2 b, F&& f) const;

 private:
  // A stretch of a -> b (as distances from a) that the pieces held do not cover, with the
  // pieces that end where it starts and start where it ends, if any.
  struct Gap {
    double from, to;
    std::optional<std::uint32_t> before, after;
  };
  std::vector<Gap> uncovered(Vec2 a, Vec2 b, double merge) const;
  // add_wall, a piece within `merge` of the walls held covering them; `exact` when touched.
  bool add_stretches(Vec2 a, Vec2 b, double merge, bool exact);
  // A touched stretch a -> b supersedes the noisy pieces it explains: of each facing the same
  // way, the part beside it within the noise of its line is dropped (the touch shows where
  // that wall is; left, a wall seen a little too near hides what lies just behind the wall).
  void supersede(Vec2 a, Vec2 b);
  // Marks the cells a -> b meets as wall cells held by piece k.
  void mark(Vec2 a, Vec2 b, std::uint32_t k);
  // Drops piece k (the last piece takes its index).
  void remove(std::uint32_t k);
  // Whether the direction d leaves p into the free side of the pieces p lies on.
  bool leaves_free(Vec2 p, Vec2 d) const;
  // The squared distance from p to cell (i, j)'s closed square.
  double cell_distance2(std::int32_t i, std::int32_t j, Vec2 p) const;

  Box bounds_;
  double h_, tol_, spread_, merge_;
  Vec2 origin_;
  std::int32_t nx_ = 0, ny_ = 0;
  std::vector<std::uint8_t> wall_;
  std::size_t wall_cells_ = 0, version_ = 0, supersessions_ = 0;
  std::vector<Piece> pieces_;
  std::vector<Piece> added_;
  std::vector<std::vector<std::uint32_t>> in_cell_;  // the pieces touching each cell
  std::vector<std::vector<std::uint32_t>> cells_;    // the cells marked for each piece
  mutable std::vector<std::uint32_t> seen_;          // per piece: the last query that met it
  mutable std::uint32_t query_ = 0;
};

template <class F>
bool SensedMap::for_each_cell(Vec2 a, Vec2 b, F&& f) const {
  return for_each_cell_on(origin_, h_, a, b, std::forward<F>(f));
}

}  // namespace covsim
