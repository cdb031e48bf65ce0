// covsim.Environment (the queries a Python planner needs) and cells of given generators,
// without a run.
#include <pybind11/stl.h>

#include "geometry/voronoi_partition.hpp"
#include "geometry_binding.hpp"
#include "scenario_binding.hpp"

namespace covsim::python {

py::list cells_of(const CellIntegrator& integrator, const VoronoiPartition& p);

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
  m.def(
      "_cells",
      [](const PyScenario& s, const py::handle& generators) {
        const std::vector<Vec2> g = to_points(generators);
        const CellIntegrator integrator(*s.parsed.environment, *s.parsed.density);
        const VoronoiPartition p(integrator, g, VoronoiPartition::Coincident::split);
        return cells_of(integrator, p);
      },
      py::arg("scenario"), py::arg("generators"));
  m.def("_environment", [](const PyScenario& s) { return PyEnvironment{s.parsed.environment}; });
}

}  // namespace covsim::python
