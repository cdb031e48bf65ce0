// The sweep runner and the run-folder reader's C++ halves; python/covsim/__init__.py wraps
// them (pandas DataFrames, numpy arrays).
#include <pybind11/stl.h>

#include "analysis/records/result_fields.hpp"
#include "analysis/sweep/sweep_runner.hpp"
#include "analysis/sweep/sweep_tables.hpp"
#include "io/output_lock.hpp"
#include "scenario_binding.hpp"

namespace covsim::python {

void bind_sweep(py::module_& m) {
  m.def(
      "measures",
      [] {
        py::list out;
        for (const Measure& x : measures()) {
          py::dict d;
          d["name"] = x.name;
          d["unit"] = x.unit;
          d["description"] = x.description;
          d["final_json"] = x.in_final();
          d["column"] = x.run_place ? py::cast(x.column()) : py::none();
          d["summarized"] = x.summarized;
          out.append(d);
        }
        return out;
      },
      "The measures of a run (docs/outputs.md): per measure a dict with its name (its JSON "
      "path in final.json when final_json is true), unit, description, column (of a sweep's "
      "runs and runs.csv; None if a sweep does not record it) and whether summary.csv "
      "summarises it.");
  m.def(
      "_sweep",
      [](const std::string& file, const std::string& out, std::size_t jobs, bool keep_series,
         const py::object& progress) {
        const SweepSpec spec = load_sweep(file);
        const OutputLock lock(out);  // one writer per folder, as `covsim sweep`
        std::vector<SweepResult> results;
        SweepOptions options{std::max<std::size_t>(1, jobs), false, 0, 1, keep_series, {}};
        // The callback runs on the sweep's threads, one call at a time, with the GIL taken; an
        // exception it raises is raised here once the runs under way have ended.
        std::optional<py::error_already_set> raised;
        if (!progress.is_none())
          options.on_progress = [&](std::size_t done, std::size_t failed, std::size_t total) {
            py::gil_scoped_acquire gil;
            if (raised) return;
            try {
              progress(done, failed, total);
            } catch (py::error_already_set& e) {
              raised = std::move(e);
            }
          };
        {
          py::gil_scoped_release release;
          results = run_sweep(spec, out, options);
          write_runs_csv(std::filesystem::path(out) / "runs.csv", spec, results);
          write_summary_csv(std::filesystem::path(out) / "summary.csv", spec, results);
        }
        if (raised) throw std::move(*raised);
        // Seeds that gave identical runs, as `covsim sweep` says on stderr.
        for (const std::string& line : identical_seed_warnings(spec, results))
          if (PyErr_WarnEx(PyExc_UserWarning, line.c_str(), 1) != 0) throw py::error_already_set();
        // The rows of runs.csv, as dicts with typed values.
        const std::vector<SweepRun> runs = spec.runs();
        py::list rows;
        for (const SweepResult& r : results) {
          const SweepRun& run = runs.at(r.index);
          py::dict row;
          row["run"] = r.index;
          row["setting"] = run.setting;
          for (std::size_t p = 0; p < spec.parameters.size(); ++p)
            row[spec.parameters[p].c_str()] = to_python(run.values[p]);
          row["seed"] = run.seed;
          for (const auto& f : run_fields()) {
            const auto it = r.values.find(f.name);
            row[f.name.c_str()] = it == r.values.end() ? py::none() : to_python(*it);
          }
          row["error"] = r.error ? py::cast(*r.error) : py::none();
          rows.append(row);
        }
        return rows;
      },
      py::arg("file"), py::arg("out"), py::arg("jobs"), py::arg("keep_series") = false,
      py::arg("progress") = py::none());
}

}  // namespace covsim::python
