// Planners and coverage laws written in Python, registered in the same registries as the
// built-in ones and selected by name in a scenario (docs/python.md). Every call from covsim
// into Python takes the GIL; Python-defined components are taken out of the registries when
// the interpreter ends.
#include <pybind11/stl.h>

#include <set>

#include "geometry/environment.hpp"
#include "geometry_binding.hpp"
#include "planners/planner_registry.hpp"
#include "robot/coverage_law_registry.hpp"
#include "robot/generator_state.hpp"
#include "scenario_binding.hpp"

namespace covsim::python {

namespace {

std::set<std::string>& python_planners() {
  static std::set<std::string> names;
  return names;
}
std::set<std::string>& python_laws() {
  static std::set<std::string> names;
  return names;
}

// A schema from {name: default}: the kind follows the default's Python type.
ParamSchema schema_of(const py::dict& params) {
  ParamSchema out;
  for (const auto& [key, value] : params) {
    const std::string name = py::str(key);
    if (py::isinstance<py::bool_>(value)) {
      out.push_back(ParamSpec::boolean(name, "").defaults_to(value.cast<bool>()));
    } else if (py::isinstance<py::int_>(value)) {
      // Whole-number parameters are counts (0 and up); a negative default means a number.
      if (value.cast<py::int_>() < py::int_(0)) {
        throw py::value_error("parameter \"" + name + "\": an int default must be 0 or more " +
                              "(int parameters are counts); give a float for a number that " +
                              "may be negative");
      }
      out.push_back(ParamSpec::integer(name, "", "").defaults_to(value.cast<std::uint64_t>()));
    } else if (py::isinstance<py::float_>(value)) {
      out.push_back(ParamSpec::number(name, "", "").defaults_to(value.cast<double>()));
    } else if (py::isinstance<py::str>(value)) {
      out.push_back(ParamSpec::text(name, "").defaults_to(value.cast<std::string>()));
    } else {
      throw py::type_error("parameter \"" + name +
                           "\": a default must be a bool, int, float or str");
    }
  }
  return out;
}

std::string type_name(const py::handle& o) {
  return py::str(py::type::of(o).attr("__name__")).cast<std::string>();
}

py::dict params_dict(const Params& p) {
  py::dict d;
  for (const auto& entry : p.values()) {
    // Named, not a structured binding: clang 14 cannot capture those in the lambda below.
    const std::string& name = entry.first;
    std::visit(
        [&](const auto& x) {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_same_v<T, std::monostate>) {
            d[name.c_str()] = py::none();
          } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::uint64_t> ||
                               std::is_same_v<T, bool> || std::is_same_v<T, std::string>) {
            d[name.c_str()] = x;
          } else if constexpr (std::is_same_v<T, Vec2>) {
            d[name.c_str()] = to_array(x);
          }
        },
        entry.second);
  }
  return d;
}

// A copy of a sensor reading, for Python, with its visible boundary taken: Python may keep it
// after the step, when the environment a lazy reading points to may be gone.
struct PyReading {
  SensorReading r;
  explicit PyReading(const SensorReading& reading) : r(reading) {
    r.set_visible(reading.visible());
  }
};

class PyPlanner final : public Planner {
 public:
  PyPlanner(PyRef obj, std::string name) : obj_(std::move(obj)), name_(std::move(name)) {
    // Read once: the controller asks at every step.
    py::gil_scoped_acquire gil;
    if (py::hasattr(*obj_, "avoids_obstacles"))
      avoids_obstacles_ = obj_->attr("avoids_obstacles").cast<bool>();
  }
  std::string_view name() const override { return name_; }
  bool avoids_obstacles() const override { return avoids_obstacles_; }
  void set_goal(Vec2 goal) override {
    py::gil_scoped_acquire gil;
    obj_->attr("set_goal")(to_array(goal));
  }
  void move_goal(Vec2 goal) override {
    py::gil_scoped_acquire gil;
    obj_->attr(py::hasattr(*obj_, "move_goal") ? "move_goal" : "set_goal")(to_array(goal));
  }
  void learn(const std::vector<SensedPiece>& walls) override {
    py::gil_scoped_acquire gil;
    if (!py::hasattr(*obj_, "learn")) return;
    py::array_t<double> rows({static_cast<py::ssize_t>(walls.size()), py::ssize_t{4}});
    auto w = rows.mutable_unchecked<2>();
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const auto i = static_cast<py::ssize_t>(k);
      w(i, 0) = walls[k].a.x;
      w(i, 1) = walls[k].a.y;
      w(i, 2) = walls[k].b.x;
      w(i, 3) = walls[k].b.y;
    }
    obj_->attr("learn")(rows);
  }
  PlanStep step(const SensorReading& reading, double max_step) override {
    py::gil_scoped_acquire gil;
    const py::object returned = obj_->attr("step")(PyReading(reading), max_step);
    if (!py::isinstance<py::tuple>(returned) && !py::isinstance<py::list>(returned))
      throw py::type_error("step must return (next, status), found " + type_name(returned));
    const py::sequence t = returned;
    if (t.size() != 2)
      throw py::value_error("step must return (next, status), found " + std::to_string(t.size()) +
                            " values");
    Vec2 next;
    try {
      next = to_point(t[0]);
    } catch (const std::exception& e) {
      throw py::value_error(std::string("step's next must be a point (x, y): ") + e.what());
    }
    try {
      return PlanStep{next, status_named(t[1].cast<std::string>())};
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string("step's status: ") + e.what());
    }
  }

 private:
  PyRef obj_;
  std::string name_;
  bool avoids_obstacles_ = true;
};

struct PyRobot {
  std::uint32_t id;
  Vec2 position, virtual_generator, virtual_target, real_target;
  std::string status;
  bool projected;
  double path_length;
};

PyRobot robot_view(const Robot& r) {
  return PyRobot{r.id,
                 r.position,
                 r.virtual_generator,
                 r.virtual_target,
                 r.real_target,
                 std::string(to_string(r.status)),
                 r.projected,
                 r.path_length};
}

// What robot i knows at one call of a Python law: its points copied, so that Python may keep
// the object; own_cell needs the live knowledge and is refused after the call.
struct PyKnowledge {
  std::vector<Vec2> points;
  std::size_t self = 0;
  const Knowledge* live = nullptr;  // set during the call only
  const CellIntegrator* integrator = nullptr;
};

class PyLaw final : public CoverageLaw {
 public:
  PyLaw(PyRef obj, Generators g, bool moves, const CellIntegrator& integrator)
      : obj_(std::move(obj)), generators_(g), moves_(moves), integrator_(integrator) {}
  Generators generators() const override { return generators_; }
  bool moves_virtual_generators() const override { return moves_; }
  Vec2 target(const Robot& robot, const Knowledge& k) override {
    py::gil_scoped_acquire gil;
    const auto view =
        std::make_shared<PyKnowledge>(PyKnowledge{k.points, k.self, &k, &integrator_});
    struct Expire {
      PyKnowledge& view;
      ~Expire() { view.live = nullptr; }
    } expire{*view};
    const py::object out = obj_->attr("target")(robot_view(robot), py::cast(view));
    try {
      return to_point(out);
    } catch (const py::error_already_set&) {
      throw;
    } catch (const std::exception& e) {
      throw py::value_error(std::string("target must return a point (x, y): ") + e.what());
    }
  }
  bool at_rest(const Robot& robot, const Tolerances& t) const override {
    py::gil_scoped_acquire gil;
    if (py::hasattr(*obj_, "at_rest"))
      return obj_->attr("at_rest")(robot_view(robot), t.position, t.virtual_generator).cast<bool>();
    return !moves_ ||
           distance(robot.virtual_target, robot.virtual_generator) <= t.virtual_generator;
  }

 private:
  PyRef obj_;
  Generators generators_;
  bool moves_;
  const CellIntegrator& integrator_;
};

template <class Entry>
py::list describe_components(const Registry<Entry>& r) {
  py::list out;
  for (const Entry& e : r.entries()) {
    py::list params;
    for (const ParamSpec& s : e.params) {
      py::dict p;
      p["name"] = s.name;
      p["kind"] = std::string(to_string(s.kind));
      p["unit"] = s.unit;
      p["default"] = s.default_value           ? py::cast(to_text(*s.default_value))
                     : !s.default_rule.empty() ? py::cast(s.default_rule)
                                               : py::none();
      p["description"] = s.description;
      params.append(p);
    }
    py::dict d;
    d["name"] = e.name;
    d["description"] = e.description;
    d["params"] = params;
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_components(py::module_& m) {
  py::class_<PyReading>(m, "SensorReading",
                        "What a robot's sensors give its planner at one step (docs/python.md).")
      .def_property_readonly("position", [](const PyReading& s) { return to_array(s.r.position); })
      .def_property_readonly(
          "origin", [](const PyReading& s) { return to_array(s.r.origin); },
          "Where the range reading was taken [m]: the position, unless it is an older one.")
      .def_property_readonly("range", [](const PyReading& s) { return s.r.range; })
      .def_property_readonly(
          "pieces",
          [](const PyReading& s) {
            py::array_t<double> a(
                {static_cast<py::ssize_t>(s.r.visible().pieces.size()), py::ssize_t{4}});
            auto w = a.mutable_unchecked<2>();
            for (std::size_t k = 0; k < s.r.visible().pieces.size(); ++k) {
              const auto& p = s.r.visible().pieces[k];
              const auto i = static_cast<py::ssize_t>(k);
              w(i, 0) = p.a.x, w(i, 1) = p.a.y, w(i, 2) = p.b.x, w(i, 3) = p.b.y;
            }
            return a;
          },
          "Visible boundary pieces within range, (k, 4) rows [ax, ay, bx, by] [m].")
      .def_property_readonly(
          "discontinuities",
          [](const PyReading& s) { return to_array(s.r.visible().discontinuities); },
          "Where the visible boundary jumps, (m, 2) [m].")
      .def_property_readonly(
          "contacts",
          [](const PyReading& s) {
            py::list out;
            for (const ContactEdge& c : s.r.contacts)
              out.append(py::make_tuple(to_array(c.a), to_array(c.b)));
            return out;
          },
          "Touched wall segments: (a, b), free space on the left of a -> b.");
  py::class_<PyRobot>(m, "Robot")
      .def_readonly("id", &PyRobot::id)
      .def_property_readonly("position", [](const PyRobot& r) { return to_array(r.position); })
      .def_property_readonly("virtual_generator",
                             [](const PyRobot& r) { return to_array(r.virtual_generator); })
      .def_property_readonly("virtual_target",
                             [](const PyRobot& r) { return to_array(r.virtual_target); })
      .def_property_readonly("real_target",
                             [](const PyRobot& r) { return to_array(r.real_target); })
      .def_readonly("status", &PyRobot::status)
      .def_readonly("projected", &PyRobot::projected)
      .def_readonly("path_length", &PyRobot::path_length);
  py::class_<PyKnowledge, std::shared_ptr<PyKnowledge>>(
      m, "Knowledge",
      "What a robot knows at its loop 1 (points may be kept; own_cell only during the call).")
      .def_property_readonly(
          "points", [](const PyKnowledge& k) { return to_array(k.points); },
          "The generators it knows, in robot-id order, (n, 2) [m].")
      .def_readonly("self", &PyKnowledge::self, "Where its own generator is in points.")
      .def(
          "own_cell",
          [](const PyKnowledge& k) {
            if (k.live == nullptr) {
              throw std::runtime_error(
                  "Knowledge.own_cell: only during the law's target call it was passed to");
            }
            const CellSummary s = own_cell_summary(*k.integrator, *k.live);
            py::dict d;
            d["mass"] = s.mass;
            d["centroid"] = to_array(s.centroid);
            d["cost"] = s.cost;
            return d;
          },
          "Its Voronoi cell ∩ Ω among the points (computed in C++): mass, centroid, cost.");

  m.def(
      "register_planner",
      [](const std::string& name, py::object factory, const std::string& description,
         const py::dict& params, bool complete, bool senses) {
        PlannerEntry e;
        e.name = name;
        e.description = description.empty() ? "a planner written in Python" : description;
        e.params = schema_of(params);
        if (!PyCallable_Check(factory.ptr()))
          throw py::type_error("register_planner(\"" + name +
                               "\"): factory must be callable, found " + type_name(factory));
        // A planner that senses is told nothing of Ω (its factory gets None), works from the
        // estimate in the odometry's frame, runs where Ω is unknown, and takes the walls its
        // robot hears through learn(walls) if it has one.
        e.senses_only = e.reads_range = senses;
        e.learns = senses && py::hasattr(factory, "learn");
        const PyRef f = hold(std::move(factory));
        e.make = [f, name, senses](const PlannerContext& ctx, const Params& p) -> PlannerSource {
          // A copy per run: Python may keep the Environment after the run has ended.
          const auto env = senses ? nullptr : std::make_shared<const Environment>(ctx.environment);
          return [f, name, env, p] {
            py::gil_scoped_acquire gil;
            const py::object told = env ? py::cast(PyEnvironment{env}) : py::none();
            return std::make_unique<PyPlanner>(hold((*f)(told, params_dict(p))), name);
          };
        };
        e.contract.complete = complete;
        planner_registry().add(std::move(e));
        python_planners().insert(name);
      },
      py::arg("name"), py::arg("factory"), py::arg("description") = "",
      py::arg("params") = py::dict(), py::arg("complete") = false, py::arg("senses") = false,
      "Registers a planner written in Python under `name`, selectable as a scenario's "
      "planner.type. factory(environment, params) makes one per robot: an object with "
      "set_goal(goal) and step(reading, max_step) -> (next, status), status one of 'moving', "
      "'reached', 'projected', 'stalled', and optionally move_goal(goal) (the goal moved "
      "while on the way; set_goal without it). params: {name: default}, validated in scenarios "
      "like a built-in planner's. complete: whether it promises to reach every reachable "
      "goal. senses: it plans from its readings alone; factory gets None for the environment; it "
      "runs where the robots do not know Ω, beside any localization, and an optional "
      "learn(walls) takes the walls, (k, 4) rows ax, ay, bx, by [m], of readings its robot "
      "hears from neighbours (docs/python.md).");
  m.def(
      "register_law",
      [](const std::string& name, py::object factory, const std::string& description,
         const py::dict& params, const std::string& generators, bool moves) {
        if (generators != "virtual_generators" && generators != "positions")
          throw py::value_error("generators: expected \"virtual_generators\" or \"positions\"");
        const Generators g =
            generators == "positions" ? Generators::positions : Generators::virtual_generators;
        LawEntry e;
        e.name = name;
        e.description = description.empty() ? "a coverage law written in Python" : description;
        e.params = schema_of(params);
        if (!PyCallable_Check(factory.ptr()))
          throw py::type_error("register_law(\"" + name + "\"): factory must be callable, found " +
                               type_name(factory));
        const PyRef f = hold(std::move(factory));
        e.make = [f, g, moves](const LawContext& ctx, const Params& p) {
          py::gil_scoped_acquire gil;
          // A copy per run: Python may keep the Environment after the run has ended.
          const auto env = std::make_shared<const Environment>(ctx.environment);
          return std::make_unique<PyLaw>(hold((*f)(PyEnvironment{env}, params_dict(p))), g, moves,
                                         ctx.integrator);
        };
        coverage_law_registry().add(std::move(e));
        python_laws().insert(name);
      },
      py::arg("name"), py::arg("factory"), py::arg("description") = "",
      py::arg("params") = py::dict(), py::arg("generators") = "virtual_generators",
      py::arg("moves_virtual_generators") = true,
      "Registers a coverage law written in Python under `name`, selectable as a scenario's "
      "controller.type. factory(environment, params) makes one per run: an object with "
      "target(robot, knowledge) -> the robot's next virtual target [m], and optionally "
      "at_rest(robot, position_tolerance, generator_tolerance) -> bool. generators: whether "
      "the law's Voronoi generators are the virtual generators or the real positions "
      "(docs/python.md).");
  m.def(
      "components",
      [](const std::string& kind) {
        if (kind == "planners") return describe_components(planner_registry());
        if (kind == "laws") return describe_components(coverage_law_registry());
        throw py::value_error("kind: expected \"planners\" or \"laws\"");
      },
      py::arg("kind"), "The registered planners or coverage laws, with their parameters.");
  // Python-defined components hold Python objects: out of the registries before the end.
  py::module_::import("atexit").attr("register")(py::cpp_function([] {
    for (const std::string& n : python_planners())
      planner_registry().remove(n);
    for (const std::string& n : python_laws())
      coverage_law_registry().remove(n);
    python_planners().clear();
    python_laws().clear();
  }));
}

}  // namespace covsim::python
