#pragma once
// A coverage law: loop 1 of the coverage controller, "what robot i knows" in, its next
// (virtual) target out. An extension point: a law is this interface plus one entry in
// coverage_law_registry(). The paper's law runs Lloyd on virtual generators that move as if
// Ω were convex; the baselines run Lloyd (Euclidean or geodesic) on the real positions.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/registry.hpp"
#include "geometry/cell_integrator.hpp"
#include "geometry/voronoi_partition.hpp"
#include "robot/own_cell_cache.hpp"
#include "robot/robot.hpp"

namespace covsim {

class GeneratorState;

// Which generators a law computes cells of.
enum class Generators {
  virtual_generators,  // the paper's: each robot's virtual generator
  positions,           // the robots' real positions
};

// What robot i knows when it runs loop 1: the generators of the robots it has heard of (all
// of them with the ideal network), in robot-id order, its own at `self`.
struct Knowledge {
  const std::vector<Vec2>& points;
  std::size_t self;
  Generators kind;
  // When the robot knows every generator as it is now (the ideal network): their shared
  // state, whose partition is computed once per change for every robot and the metrics,
  // and whose version changes whenever a generator moves (for a law's own caches).
  const GeneratorState* shared = nullptr;
  std::optional<std::uint64_t> version;
  // Otherwise, where the robot keeps its own cell between loop-1 updates (may be null).
  OwnCellCache* cache = nullptr;
  // For a robot that maps Ω: its cells are of Ω as it believes it (robot/mapping.hpp), not
  // of the law's, and the shared partition, if any, is `believed`: of the generators it knows
  // in that belief (null: none).
  const CellIntegrator* integrator = nullptr;
  const VoronoiPartition* believed = nullptr;
  // The shared partition, if there is one (computed on first use): in the robot's belief, for
  // a robot that maps Ω.
  const VoronoiPartition* partition() const;
};

struct Tolerances {
  double position;           // a robot is at its target
  double virtual_generator;  // a virtual generator is at its target
};

class CoverageLaw {
 public:
  virtual ~CoverageLaw() = default;
  virtual Generators generators() const = 0;
  // Whether virtual generators step toward the virtual targets as if Ω were convex
  // (Algorithm 2, line 6); otherwise they follow the positions.
  virtual bool moves_virtual_generators() const = 0;
  // Loop 1 for robot i: its new virtual target.
  virtual Vec2 target(const Robot& robot, const Knowledge& knowledge) = 0;
  // The law's own part of a robot's convergence test (the controller checks that the robot
  // has settled at its real target): by default, nothing more.
  virtual bool at_rest(const Robot& robot, const Tolerances& tolerances) const;
};

struct LawContext {
  const Environment& environment;
  const Density& density;
  const CellIntegrator& integrator;
};

// What a law promises, checked by the law contract suite (analysis/contract/law_contract).
struct LawContract {
  // Lloyd's step in any Ω: its target is the centroid of the robot's Voronoi cell ∩ Ω among
  // the generators it knows, so a step of every robot to its target never raises the
  // coverage cost H, and a centroidal configuration is at rest.
  bool lloyd = false;
  // In a convex Ω, where every distance is Euclidean: how far its target may lie from the
  // segment from its generator to its cell's centroid (a Lloyd step, damped or not), for its
  // parameters in that Ω; unset: no promise beyond `lloyd`'s.
  std::function<double(const Environment&, const Params&)> convex_step_tolerance;
};

struct LawEntry : ComponentInfo {
  std::function<std::unique_ptr<CoverageLaw>(const LawContext&, const Params&)> make;
  // Optional: checks that need the environment, run when a scenario is loaded.
  std::function<void(const Environment&, const Params&)> check;
  // Whether it computes its own targets (a coverage law proper); false for a law whose
  // targets a driving program sets (external), which comparisons of laws leave out.
  bool autonomous = true;
  // Whether it needs Ω itself beyond cells of what a robot believes Ω is (geodesic
  // distances): refused for robots that do not know Ω.
  bool needs_map = false;
  LawContract contract;
};

// A scenario's "controller": the law, and its parameters validated against its schema.
struct LawConfig {
  std::string type = "virtual_generators";
  Params params;
};

// The centroid of robot i's Voronoi cell among the generators it knows: from the shared
// partition when there is one, else from its own cell (computed as the partition would).
CellSummary own_cell_summary(const CellIntegrator& integrator, const Knowledge& k,
                             ConvexPolygon* cell = nullptr);

}  // namespace covsim
