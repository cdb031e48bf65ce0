// covsim.Environment (the queries a Python planner needs) and cells of given generators,
// without a run: covsim.Cells keeps Ω, φ and their integrator between calls, so a call
// costs what the partition costs.
#include <pybind11/stl.h>

#include <memory>

#include "geometry/cell_integrator.hpp"
#include "geometry/geometry_error.hpp"
#include "geometry/voronoi_partition.hpp"
#include "geometry_binding.hpp"
#include "scenario_binding.hpp"

namespace covsim::python {

py::list cells_of(const CellIntegrator& integrator, const VoronoiPartition& p);

namespace {

// Ω, φ and the integrator over them, parsed and built once.
struct PyCells {
  std::shared_ptr<const Environment> environment;
  std::shared_ptr<const Density> density;
  std::unique_ptr<const CellIntegrator> integrator;
  explicit PyCells(const PyScenario& s)
      : environment(s.parsed.environment),
        density(s.parsed.density),
        integrator(std::make_unique<const CellIntegrator>(*environment, *density)) {}
};

// The partition of one call, with every cell's moments; it keeps its PyCells alive.
struct PyPartition {
  std::shared_ptr<const PyCells> cells;
  VoronoiPartition partition;
  std::vector<CellSummary> summaries;

  PyPartition(std::shared_ptr<const PyCells> c, std::vector<Vec2> generators)
      : cells(std::move(c)),
        // Coincident generators refused, as `covsim cells` refuses them.
        partition(*cells->integrator, std::move(generators), VoronoiPartition::Coincident::reject) {
    summaries.reserve(partition.size());
    for (std::size_t i = 0; i < partition.size(); ++i)
      summaries.push_back(partition.summary(i));
  }
  std::size_t index(py::ssize_t i) const {
    const auto n = static_cast<py::ssize_t>(partition.size());
    if (i < -n || i >= n)
      throw py::index_error("cell " + std::to_string(i) + " of " + std::to_string(n));
    return static_cast<std::size_t>(i < 0 ? i + n : i);
  }
  template <class F>
  py::array_t<double> column(F f) const {
    py::array_t<double> a(static_cast<py::ssize_t>(summaries.size()));
    auto out = a.mutable_unchecked<1>();
    for (std::size_t i = 0; i < summaries.size(); ++i)
      out(static_cast<py::ssize_t>(i)) = f(summaries[i]);
    return a;
  }
};

}  // namespace

void bind_geometry(py::module_& m) {
  py::class_<PyEnvironment>(m, "Environment",
                            "Ω: an outer ring and holes. Points on the boundary count as inside.")
      .def_property_readonly(
          "rings",
          [](const PyEnvironment& e) {
            py::list out;
            for (const auto& r : e.env->rings())
              out.append(to_array(r));
            return out;
          },
          "The outer ring (counter-clockwise) then the holes (clockwise), (k, 2) arrays [m].")
      .def_property_readonly(
          "bounds",
          [](const PyEnvironment& e) {
            return to_array(std::vector<Vec2>{e.env->bounds().lo, e.env->bounds().hi});
          },
          "[[x_min, y_min], [x_max, y_max]] [m].")
      .def_property_readonly("diameter", [](const PyEnvironment& e) { return e.env->diameter(); })
      .def_property_readonly("area", [](const PyEnvironment& e) { return e.env->area(); })
      .def("contains",
           [](const PyEnvironment& e, const py::handle& p) { return e.env->contains(to_point(p)); })
      .def("segment_inside",
           [](const PyEnvironment& e, const py::handle& a, const py::handle& b) {
             return e.env->segment_inside(to_point(a), to_point(b));
           })
      .def("closest_point", [](const PyEnvironment& e, const py::handle& p) {
        return to_array(e.env->closest_point(to_point(p)));
      });
  m.def("_environment", [](const PyScenario& s) { return PyEnvironment{s.parsed.environment}; });

  py::class_<PyPartition>(m, "Partition",
                          "The Voronoi partition of Ω by generators, with each cell's moments "
                          "(what Cells returns).")
      .def("__len__", [](const PyPartition& p) { return p.partition.size(); })
      .def_property_readonly(
          "generators", [](const PyPartition& p) { return to_array(p.partition.generators()); },
          "(n, 2) [m].")
      .def_property_readonly(
          "mass",
          [](const PyPartition& p) {
            return p.column([](const CellSummary& c) { return c.mass; });
          },
          "∫φ over each cell ∩ Ω, (n,) [m²·φ].")
      .def_property_readonly(
          "centroid",
          [](const PyPartition& p) {
            std::vector<Vec2> c;
            c.reserve(p.summaries.size());
            for (const CellSummary& s : p.summaries)
              c.push_back(s.centroid);
            return to_array(c);
          },
          "Each cell ∩ Ω's centroid, (n, 2) [m] (its generator when the mass is zero).")
      .def_property_readonly(
          "cost",
          [](const PyPartition& p) {
            return p.column([](const CellSummary& c) { return c.cost; });
          },
          "½∫|x - g|²φ over each cell ∩ Ω about its generator, (n,) [m⁴·φ].")
      .def(
          "cell",
          [](const PyPartition& p, py::ssize_t i) {
            const auto c = p.partition.cell(p.index(i));
            return to_array(std::vector<Vec2>(c.begin(), c.end()));
          },
          py::arg("i"), "Cell i, clipped to Ω's bounding box, counter-clockwise, (k, 2) [m].")
      .def(
          "pieces",
          [](const PyPartition& p, py::ssize_t i) {
            const auto c = p.partition.cell(p.index(i));
            py::list out;
            p.cells->integrator->for_each_piece(
                ConvexPolygon(c.begin(), c.end()),
                [&](const ConvexPolygon& piece) { out.append(to_array(piece)); });
            return out;
          },
          py::arg("i"), "The convex pieces of cell i ∩ Ω, a list of (k, 2) arrays [m].")
      .def(
          "to_list",
          [](const PyPartition& p) { return cells_of(*p.cells->integrator, p.partition); },
          "Per generator a dict: generator, cell, pieces, mass, centroid, cost (covsim.cells).");

  py::class_<PyCells, std::shared_ptr<PyCells>>(
      m, "_Cells", "Ω and φ of a scenario, parsed once, for the cells of any generators.")
      .def(py::init([](const PyScenario& s) { return std::make_shared<PyCells>(s); }),
           py::arg("scenario"))
      .def(
          "__call__",
          [](const std::shared_ptr<PyCells>& c, const py::handle& generators) {
            std::vector<Vec2> g = to_points(generators);
            try {
              py::gil_scoped_release release;
              return std::make_unique<PyPartition>(c, std::move(g));
            } catch (const GeometryError& e) {
              throw py::value_error(std::string("cells(generators): ") + e.what());
            }
          },
          py::arg("generators"))
      .def_property_readonly(
          "total_mass", [](const PyCells& c) { return c.integrator->total_mass(); },
          "∫φ over Ω [m²·φ].");
}

}  // namespace covsim::python
