#pragma once
// The pieces of the Python module `covsim._covsim`, one per concept; module.cpp calls them.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <vector>

#include "core/vec2.hpp"

namespace covsim::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_scenario(py::module_& m);
void bind_simulation(py::module_& m);
void bind_geometry(py::module_& m);
void bind_components(py::module_& m);
void bind_sweep(py::module_& m);

// Points as an (n, 2) float64 array (a copy), and back.
py::array_t<double> to_array(const std::vector<Vec2>& points);
py::array_t<double> to_array(Vec2 p);
Vec2 to_point(const py::handle& h);
std::vector<Vec2> to_points(const py::handle& h);

// A Python object held from C++: copies share it without touching its reference count, and
// the last one lets it go with the GIL held, whatever thread that happens on.
using PyRef = std::shared_ptr<py::object>;
PyRef hold(py::object o);

}  // namespace covsim::python
