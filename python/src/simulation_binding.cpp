// covsim.Simulation: one run under Python's control, event by event or up to a time, with its
// state as numpy arrays. The GIL is released while covsim runs; observers, Python planners
// and laws take it back when they are called.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "analysis/records/result_fields.hpp"
#include "core/fingerprint.hpp"
#include "planners/tangent_bug.hpp"
#include "scenario_binding.hpp"
#include "sim/simulation.hpp"
#include "sim/timed_planner.hpp"

namespace covsim::python {

namespace {

class PySimulation;

// Calls the Python observers at every sample.
class PyObservers final : public CoverageObserver {
 public:
  explicit PyObservers(PySimulation* owner) : owner_(owner) {}
  void on_sample(SimTime t, const CoverageController&) override;
  std::vector<PyRef> callbacks;

 private:
  PySimulation* owner_;
};

class PySimulation {
 public:
  PySimulation(const PyScenario& s, std::optional<std::uint64_t> seed)
      : scenario_(s), sim_(s.parsed, seed), observers_(this) {
    sim_.add_observer(&observers_);
  }
  Simulation& sim() { return sim_; }
  const PyScenario& scenario() const { return scenario_; }
  void add_observer(py::object f) { observers_.callbacks.push_back(hold(std::move(f))); }

 private:
  PyScenario scenario_;
  Simulation sim_;
  PyObservers observers_;
};

void PyObservers::on_sample(SimTime t, const CoverageController&) {
  if (callbacks.empty()) return;
  py::gil_scoped_acquire gil;
  const py::object self = py::cast(owner_, py::return_value_policy::reference);
  for (const PyRef& f : callbacks)
    (*f)(t.seconds(), self);
}

const VoronoiPartition& partition(const CoverageController& c, const std::string& kind) {
  if (kind == "real") return c.real_partition();
  if (kind == "virtual") return c.virtual_partition();
  throw py::value_error("kind: expected \"real\" or \"virtual\", found \"" + kind + "\"");
}

}  // namespace

// Each cell ∩ Ω of a partition: its convex pieces, mass, centroid and cost.
py::list cells_of(const CellIntegrator& integrator, const VoronoiPartition& p) {
  py::list out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto cell = p.cell(i);
    const ConvexPolygon polygon(cell.begin(), cell.end());
    py::list pieces;
    integrator.for_each_piece(polygon, [&](const ConvexPolygon& piece) {
      pieces.append(to_array(std::vector<Vec2>(piece.begin(), piece.end())));
    });
    const CellSummary s = p.summary(i);
    py::dict d;
    d["generator"] = to_array(p.generators()[i]);
    d["cell"] = to_array(std::vector<Vec2>(polygon.begin(), polygon.end()));
    d["pieces"] = pieces;
    d["mass"] = s.mass;
    d["centroid"] = to_array(s.centroid);
    d["cost"] = s.cost;
    out.append(d);
  }
  return out;
}

void bind_simulation(py::module_& m) {
  using R = const std::vector<Robot>&;
  const auto robots = [](PySimulation& s) -> R { return s.sim().controller().robots(); };
  const auto points = [robots](Vec2 Robot::*member) {
    return [robots, member](PySimulation& s) {
      std::vector<Vec2> out;
      for (const Robot& r : robots(s))
        out.push_back(r.*member);
      return to_array(out);
    };
  };
  // One value per robot, as a 1-d array.
  const auto column = [robots](auto Robot::*member) {
    return [robots, member](PySimulation& s) {
      using T = std::decay_t<decltype(std::declval<Robot>().*member)>;
      py::array_t<T> a(static_cast<py::ssize_t>(robots(s).size()));
      auto out = a.template mutable_unchecked<1>();
      for (std::size_t i = 0; i < robots(s).size(); ++i)
        out(static_cast<py::ssize_t>(i)) = robots(s)[i].*member;
      return a;
    };
  };
  py::class_<PySimulation>(m, "Simulation",
                           "One run of a scenario, driven from Python (docs/python.md).")
      .def(py::init<const PyScenario&, std::optional<std::uint64_t>>(), py::arg("scenario"),
           py::arg("seed") = py::none(), "seed, if given, replaces the scenario's.")
      .def(
          "step",
          [](PySimulation& s) {
            py::gil_scoped_release release;
            return s.sim().step();
          },
          "Dispatches one event; False once the run has ended.")
      .def(
          "run_until",
          [](PySimulation& s, double t) {
            py::gil_scoped_release release;
            s.sim().run_until(SimTime::from_seconds(t));
          },
          py::arg("t"), "Runs to simulated time t [s] (or to the end of the run, if sooner).")
      .def(
          "advance",
          [](PySimulation& s, double dt) {
            if (!(dt >= 0.0)) throw py::value_error("advance: expected dt >= 0");
            py::gil_scoped_release release;
            s.sim().run_until(s.sim().now() + SimTime::from_seconds(dt));
          },
          py::arg("dt"), "Runs for dt more simulated seconds (or to the end of the run).")
      .def(
          "run",
          [](PySimulation& s) {
            {
              py::gil_scoped_release release;
              s.sim().run();
            }
            return to_python(to_json_object(final_fields(), s.sim().outcome()));
          },
          "Runs to the end; the outcome, as final.json (docs/outputs.md).")
      .def(
          "outcome",
          [](PySimulation& s) {
            return to_python(to_json_object(final_fields(), s.sim().outcome()));
          },
          "The outcome so far, as final.json would hold it (stop_reason 'running' before the "
          "end).")
      .def("add_observer", &PySimulation::add_observer, py::arg("callback"),
           "callback(t, simulation) at every metrics sample (metrics.period).")
      .def(
          "set_target",
          [](PySimulation& s, std::uint32_t robot, const py::handle& target) {
            s.sim().set_target(robot, to_point(target));
          },
          py::arg("robot"), py::arg("target"),
          "With the 'external' coverage law: robot's next target [m].")
      .def(
          "cells",
          [](PySimulation& s, const std::string& kind) {
            const CoverageController& c = s.sim().controller();
            return cells_of(c.integrator(), partition(c, kind));
          },
          py::arg("kind") = "real",
          "The Voronoi partition of the real positions ('real') or of the virtual generators "
          "('virtual'): per robot a dict with the generator, its cell (clipped to Ω's box), "
          "the convex pieces of the cell ∩ Ω, mass, centroid and cost.")
      .def(
          "cost",
          [](PySimulation& s, const std::string& kind) {
            return partition(s.sim().controller(), kind).cost();
          },
          py::arg("kind") = "real", "H of the real positions or the virtual generators now.")
      .def_property_readonly("scenario", &PySimulation::scenario)
      .def_property_readonly(
          "now", [](PySimulation& s) { return s.sim().now().seconds(); }, "Simulated time [s].")
      .def_property_readonly("finished", [](PySimulation& s) { return s.sim().finished(); })
      .def_property_readonly("events", [](PySimulation& s) { return s.sim().events(); })
      .def_property_readonly(
          "fingerprint", [](PySimulation& s) { return Fingerprint::to_hex(s.sim().fingerprint()); },
          "The run's fingerprint so far, 16 hex digits (as covsim run prints it at the end).")
      .def_property_readonly("stop_reason",
                             [](PySimulation& s) { return s.sim().outcome().stop_reason; })
      .def_property_readonly("positions", points(&Robot::position),
                             "Real generators, an (n, 2) array [m].")
      .def_property_readonly("virtual_generators", points(&Robot::virtual_generator),
                             "Virtual generators, an (n, 2) array [m].")
      .def_property_readonly("virtual_targets", points(&Robot::virtual_target),
                             "Loop-1 targets, an (n, 2) array [m].")
      .def_property_readonly("real_targets", points(&Robot::real_target),
                             "Real targets (projected onto Ω), an (n, 2) array [m].")
      .def_property_readonly("goals", points(&Robot::goal),
                             "The goals the planners work on, an (n, 2) array [m].")
      .def_property_readonly("path_lengths", column(&Robot::path_length),
                             "Distance each robot has travelled [m].")
      .def_property_readonly("projected", column(&Robot::projected),
                             "Whether each virtual target lies outside Ω.")
      .def(
          "planner_state",
          [robots](PySimulation& s) {
            py::list out;
            for (const Robot& r : robots(s)) {
              py::dict d;
              const Planner* p = r.planner.get();
              if (const auto* timed = dynamic_cast<const TimedPlanner*>(p)) p = &timed->inner();
              d["planner"] = std::string(p->name());
              d["status"] = std::string(to_string(r.status));
              d["goal"] = to_array(r.goal);
              if (const auto* bug = dynamic_cast<const TangentBug*>(p))
                d["mode"] = std::string(to_string(bug->mode()));
              out.append(d);
            }
            return out;
          },
          "Per robot: its planner, status (moving, reached, projected, stalled), goal, and "
          "TangentBug's mode.");
}

}  // namespace covsim::python
