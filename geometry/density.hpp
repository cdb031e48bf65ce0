#pragma once
// The density φ: how much each point of Ω matters. Integrated over convex pieces of Ω
// (φ is zero outside Ω, which the callers ensure by integrating only over Ω). An extension
// point: a density is this interface plus one entry in density_registry().
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include "core/registry.hpp"
#include "geometry/convex_polygon.hpp"

namespace covsim {

class Environment;

class Density {
 public:
  virtual ~Density() = default;
  virtual double operator()(Vec2 x) const = 0;
  // Moments of φ over a convex polygon (counter-clockwise) relative to r.
  virtual Moments integrate(const ConvexPolygon& piece, Vec2 r) const = 0;
  // Uniform densities let cell integrals take exact polygon moments.
  virtual bool is_uniform() const { return false; }
};

// What a density's factory may consult: the environment (a raster must cover it), the
// folder the scenario file is in (files it names are relative to it) and the scenario's seed
// (for what is drawn per seed; unset when the scenario has none).
struct DensityContext {
  const Environment& environment;
  std::filesystem::path base_dir;
  std::optional<std::uint64_t> seed;
};

using DensityEntry =
    Component<std::function<std::shared_ptr<const Density>(const DensityContext&, const Params&)>>;

}  // namespace covsim
