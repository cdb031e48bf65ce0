#pragma once
// The Voronoi partition of Ω by a set of generators, with each cell's moments of φ.
//
// The Delaunay triangulation is computed at construction; a cell is clipped and integrated
// the first time it is asked for, and kept. A robot's loop 1 reads its own cell only, so a
// tick in which a few robots update costs one triangulation and a few cells, not N. The
// lazy state makes concurrent reads of one partition unsafe; every run owns its own.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/cell_integrator.hpp"
#include "geometry/delaunay.hpp"

namespace covsim {

class VoronoiPartition {
 public:
  enum class Coincident {
    reject,  // throw GeometryError naming the pair
    split,   // equal generators split their cell into wedges, in index order (clip_to_wedge)
  };
  // Cells from the generators' Delaunay neighbours. Throws GeometryError for non-finite
  // generators, for generators more than 100 times the integrator's box size outside it,
  // and for coincident ones unless told to split.
  VoronoiPartition(const CellIntegrator& integrator, std::vector<Vec2> generators,
                   Coincident coincident = Coincident::reject);
  // The same, keeping the cells `previous` has computed whose generator, place among
  // coincident generators and Delaunay neighbours (in order) are the same bit for bit, so
  // the same cell would be clipped: after a few generators move, only the cells around
  // them are clipped again. Nothing is kept across different integrators. The kept cells
  // are moved out of `previous`, which is spent.
  VoronoiPartition(const CellIntegrator& integrator, std::vector<Vec2> generators,
                   Coincident coincident, VoronoiPartition&& previous);

  std::size_t size() const { return generators_.size(); }
  const std::vector<Vec2>& generators() const { return generators_; }
  // Cell i (clipped to the integrator's box, counter-clockwise; empty if it misses it). The
  // span stays valid as long as the partition.
  std::span<const Vec2> cell(std::size_t i) const { return computed(i).vertices; }
  // Moments of φ over cell i ∩ Ω about generator i.
  const Moments& moments(std::size_t i) const { return computed(i).moments; }
  CellSummary summary(std::size_t i) const { return summarize(moments(i), generators_[i]); }
  // H(P, V) = Σ_i ½ ∫_{V_i ∩ Ω} |x - p_i|² φ for points P on this partition (the paper's
  // Remark 1 compares such costs); cost(generators()) is the partition's own cost.
  double cost(std::span<const Vec2> points) const;
  double cost() const { return cost(generators_); }
  // How many cells have been clipped so far, not counting those kept from a previous
  // partition (for tests and benchmarks of the laziness).
  std::size_t cells_computed() const { return cells_computed_; }

  // The distinct points among the generators, and for each generator the index of its
  // point, its rank among the generators at that point (in index order) and how many share
  // it.
  struct Coincidence {
    std::vector<Vec2> distinct;
    std::vector<std::size_t> point, rank, count;
  };

 private:
  struct Cell {
    bool done = false;
    ConvexPolygon vertices;
    Moments moments;
  };
  const Cell& computed(std::size_t i) const;
  // Whether cell i's inputs are the same, bit for bit, as cell i's of `other`.
  bool same_inputs(std::size_t i, const VoronoiPartition& other) const;

  const CellIntegrator& integrator_;
  std::vector<Vec2> generators_;
  Coincidence coincidence_;
  DelaunayNeighbors neighbors_;
  mutable std::vector<Cell> cells_;
  mutable std::size_t cells_computed_ = 0;
};

// The cell of generators[self] alone, as VoronoiPartition(..., split) gives it: what a robot
// computes from the generators it knows of.
void voronoi_cell(const CellIntegrator& integrator, std::span<const Vec2> generators,
                  std::size_t self, ConvexPolygon& out);

}  // namespace covsim
