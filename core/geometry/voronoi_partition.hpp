#pragma once
// The Voronoi partition of Ω by a set of generators, with each cell's moments of φ.
#include <span>
#include <vector>

#include "core/geometry/cell_integrator.hpp"

namespace covsim {

class VoronoiPartition {
 public:
  enum class Coincident {
    reject,  // throw GeometryError naming the pair
    split,   // equal generators split their cell into wedges, in index order (clip_to_wedge)
  };
  // Cells from the generators' Delaunay neighbours. Throws GeometryError for non-finite
  // generators, and for coincident ones unless told to split.
  VoronoiPartition(const CellIntegrator& integrator, std::vector<Vec2> generators,
                   Coincident coincident = Coincident::reject);

  std::size_t size() const { return generators_.size(); }
  const std::vector<Vec2>& generators() const { return generators_; }
  // Cell i (clipped to the integrator's box, counter-clockwise; empty if it misses it).
  std::span<const Vec2> cell(std::size_t i) const {
    return {vertices_.data() + start_[i], vertices_.data() + start_[i + 1]};
  }
  // Moments of φ over cell i ∩ Ω about generator i.
  const Moments& moments(std::size_t i) const { return moments_[i]; }
  CellSummary summary(std::size_t i) const { return summarize(moments_[i], generators_[i]); }
  // H(P, V) = Σ_i ½ ∫_{V_i ∩ Ω} |x - p_i|² φ for points P on this partition (the paper's
  // Remark 1 compares such costs); cost(generators()) is the partition's own cost.
  double cost(std::span<const Vec2> points) const;
  double cost() const { return cost(generators_); }

 private:
  std::vector<Vec2> generators_;
  std::vector<Vec2> vertices_;
  std::vector<std::size_t> start_;
  std::vector<Moments> moments_;
};

// The cell of generators[self] alone, as VoronoiPartition(..., split) gives it: what a robot
// computes from the generators it knows of.
void voronoi_cell(const CellIntegrator& integrator, std::span<const Vec2> generators,
                  std::size_t self, ConvexPolygon& out);

}  // namespace covsim
