// covsim.Simulation: one run under Python's control, event by event or up to a time, with its
// state as numpy arrays. The GIL is released while covsim runs; observers, Python planners
// and laws take it back when they are called.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <atomic>
#include <cmath>
#include <thread>

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
  // The simulation to read, from the thread that may: any, while it is not running; only
  // its own (observers, planners, laws) while it runs, since covsim runs without the GIL.
  Simulation& sim(const char* call) {
    if (running_ && std::this_thread::get_id() != runner_)
      throw std::runtime_error(std::string("Simulation.") + call +
                               ": the simulation is running in another thread; wait for it");
    return sim_;
  }
  // Runs f (the GIL released) as the one run in progress: a second thread, or a call from
  // inside the run (an observer, planner or law calling run), is refused.
  template <class F>
  auto run(const char* call, F&& f) {
    if (running_) {
      throw std::runtime_error(
          std::string("Simulation.") + call +
          (std::this_thread::get_id() == runner_
               ? ": called from inside the simulation's own run (an observer, planner or law)"
               : ": the simulation is running in another thread; wait for it"));
    }
    running_ = true;
    runner_ = std::this_thread::get_id();
    struct Done {
      PySimulation* self;
      ~Done() { self->running_ = false; }
    } done{this};
    py::gil_scoped_release release;
    return f(sim_);
  }
  const PyScenario& scenario() const { return scenario_; }
  void add_observer(py::object f) { observers_.callbacks.push_back(hold(std::move(f))); }

 private:
  PyScenario scenario_;
  Simulation sim_;
  PyObservers observers_;
  std::atomic<bool> running_ = false;
  std::thread::id runner_;
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
  const auto robots = [](PySimulation& s) -> R { return s.sim("robots").controller().robots(); };
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
            return s.run("step()", [](Simulation& sim) { return sim.step(); });
          },
          "Dispatches one event; False once the run has ended.")
      .def(
          "run_until",
          [](PySimulation& s, double t) {
            const std::string call = fmt::format("run_until({})", t);
            const Simulation& sim = s.sim(call.c_str());
            if (!std::isfinite(t)) throw py::value_error(call + ": expected a finite time [s]");
            if (t < sim.now().seconds())
              throw py::value_error(
                  fmt::format("{}: that is before now, {} s", call, sim.now().seconds()));
            s.run(call.c_str(), [t](Simulation& r) { r.run_until(SimTime::from_seconds(t)); });
          },
          py::arg("t"),
          "Runs to simulated time t [s] (or to the end of the run, if sooner); a time before "
          "now is a ValueError.")
      .def(
          "advance",
          [](PySimulation& s, double dt) {
            const std::string call = fmt::format("advance({})", dt);
            if (!(dt >= 0.0) || !std::isfinite(dt))
              throw py::value_error(call + ": expected a finite dt >= 0 [s]");
            if (s.sim(call.c_str()).finished())
              throw py::value_error(call + ": the run has ended (" +
                                    s.sim(call.c_str()).outcome().stop_reason +
                                    "); make a new Simulation to run again");
            s.run(call.c_str(),
                  [dt](Simulation& r) { r.run_until(r.now() + SimTime::from_seconds(dt)); });
          },
          py::arg("dt"),
          "Runs for dt more simulated seconds (or to the end of the run); after the end, a "
          "ValueError.")
      .def(
          "run",
          [](PySimulation& s) {
            s.run("run()", [](Simulation& sim) { sim.run(); });
            return to_python(to_json_object(final_fields(), s.sim("run()").outcome()));
          },
          "Runs to the end; the outcome, as final.json (docs/outputs.md).")
      .def(
          "outcome",
          [](PySimulation& s) {
            return to_python(to_json_object(final_fields(), s.sim("outcome()").outcome()));
          },
          "The outcome so far, as final.json would hold it (stop_reason 'running' before the "
          "end).")
      .def("add_observer", &PySimulation::add_observer, py::arg("callback"),
           "callback(t, simulation) at every metrics sample (metrics.period).")
      .def(
          "set_target",
          [](PySimulation& s, std::uint32_t robot, const py::handle& target) {
            const Vec2 t = to_point(target);
            const std::string call = fmt::format("set_target({}, ({}, {}))", robot, t.x, t.y);
            if (!is_finite(t)) throw py::value_error(call + ": expected a finite point [m]");
            Simulation& sim = s.sim(call.c_str());
            try {
              sim.set_target(robot, t);
            } catch (const std::exception& e) {
              throw py::value_error(call + ": " + e.what());
            }
          },
          py::arg("robot"), py::arg("target"),
          "With the 'external' coverage law: robot's next target [m].")
      .def(
          "cells",
          [](PySimulation& s, const std::string& kind) {
            const CoverageController& c = s.sim("cells()").controller();
            return cells_of(c.integrator(), partition(c, kind));
          },
          py::arg("kind") = "real",
          "The Voronoi partition of the real positions ('real') or of the virtual generators "
          "('virtual'): per robot a dict with the generator, its cell (clipped to Ω's box), "
          "the convex pieces of the cell ∩ Ω, mass, centroid and cost.")
      .def(
          "cost",
          [](PySimulation& s, const std::string& kind) {
            return partition(s.sim("cost()").controller(), kind).cost();
          },
          py::arg("kind") = "real", "H of the real positions or the virtual generators now.")
      .def_property_readonly("scenario", &PySimulation::scenario)
      .def_property_readonly(
          "now", [](PySimulation& s) { return s.sim("now").now().seconds(); },
          "Simulated time [s].")
      .def_property_readonly("finished",
                             [](PySimulation& s) { return s.sim("finished").finished(); })
      .def_property_readonly("events", [](PySimulation& s) { return s.sim("events").events(); })
      .def_property_readonly(
          "fingerprint",
          [](PySimulation& s) { return Fingerprint::to_hex(s.sim("fingerprint").fingerprint()); },
          "The run's fingerprint so far, 16 hex digits (as covsim run prints it at the end).")
      .def_property_readonly(
          "stop_reason", [](PySimulation& s) { return s.sim("stop_reason").outcome().stop_reason; })
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
              d["planner_goal"] = to_array(r.planner_goal);
              if (const auto* bug = dynamic_cast<const TangentBug*>(p))
                d["mode"] = std::string(to_string(bug->mode()));
              out.append(d);
            }
            return out;
          },
          "Per robot: its planner, status (moving, reached, projected, stalled), goal, the "
          "goal in the frame the planner works in (its odometry's), and TangentBug's mode.");
}

}  // namespace covsim::python
