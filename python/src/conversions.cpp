#include "bindings.hpp"

namespace covsim::python {

py::array_t<double> to_array(const std::vector<Vec2>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    r(static_cast<py::ssize_t>(i), 0) = points[i].x;
    r(static_cast<py::ssize_t>(i), 1) = points[i].y;
  }
  return a;
}

py::array_t<double> to_array(Vec2 p) {
  py::array_t<double> a(2);
  auto r = a.mutable_unchecked<1>();
  r(0) = p.x;
  r(1) = p.y;
  return a;
}

Vec2 to_point(const py::handle& h) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
  if (!a || a.size() != 2) throw py::value_error("expected a point (x, y)");
  return {a.at(0), a.at(1)};
}

std::vector<Vec2> to_points(const py::handle& h) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
  const bool table = a && a.ndim() == 2 && a.shape(1) == 2;
  const bool empty = a && a.ndim() == 1 && a.size() == 0;
  if (!table && !empty) throw py::value_error("expected an (n, 2) array of points");
  std::vector<Vec2> out;
  if (a.size() == 0) return out;
  auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    out.push_back({r(i, 0), r(i, 1)});
  return out;
}

PyRef hold(py::object o) {
  return PyRef(new py::object(std::move(o)), [](py::object* p) {
    py::gil_scoped_acquire gil;
    delete p;
  });
}

}  // namespace covsim::python
