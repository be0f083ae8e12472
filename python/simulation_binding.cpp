#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "field_arrays.hpp"
#include "locked.hpp"
#include "scene_argument.hpp"
#include "tide/solvers/probes.hpp"

namespace py = pybind11;

namespace tide::python {
namespace {

// How long run() keeps the GIL released before it looks for Ctrl-C (KeyboardInterrupt).
constexpr std::chrono::duration<double> signal_check_interval{0.2};

py::dict solve_dict(const SolveReport& solve) {
  py::dict d;
  d["iterations"] = solve.iterations;
  d["error"] = solve.error;
  d["converged"] = solve.converged;
  return d;
}

py::dict report_dict(const StepReport& report) {
  py::dict d;
  d["dt"] = static_cast<double>(report.time_step.dt);
  d["limit"] = std::string(time_step_limit_name(report.time_step.limit));
  d["removed"] = report.removed;
  d["density_solve"] = report.density_solve ? py::object(solve_dict(*report.density_solve)) : py::none();
  d["divergence_solve"] = report.divergence_solve ? py::object(solve_dict(*report.divergence_solve)) : py::none();
  return d;
}

py::dict tally_dict(const SolveTally& tally) {
  py::dict d;
  d["solves"] = tally.solves;
  d["missed"] = tally.missed;
  d["mean_iterations"] = tally.mean_iterations();
  d["max_iterations"] = tally.max_iterations;
  d["mean_error"] = tally.mean_error();
  d["max_error"] = tally.max_error;
  return d;
}

/// What statistics() reports, copied under the lock.
struct StatisticsSnapshot {
  RunStatistics run;
  std::size_t neighbor_builds = 0;
  std::size_t removed_total = 0;
  std::vector<std::pair<std::string, double>> stages;
};

py::dict statistics_dict(const StatisticsSnapshot& snapshot) {
  const RunStatistics& run = snapshot.run;
  py::dict d;
  d["steps"] = run.steps;
  d["particle_steps"] = run.particle_steps;
  d["wall_seconds"] = run.wall_seconds;
  d["particle_steps_per_second"] = run.wall_seconds > 0 ? run.particle_steps / run.wall_seconds : 0.0;
  py::dict limits;
  for (std::size_t k = 0; k < time_step_limit_count; ++k)
    limits[py::str(std::string(time_step_limit_name(static_cast<TimeStepLimit>(k))))] = run.limits.counts[k];
  d["limits"] = limits;
  d["density_solves"] = tally_dict(run.density_solves);
  d["divergence_solves"] = tally_dict(run.divergence_solves);
  d["last_step"] = run.last ? py::object(report_dict(*run.last)) : py::none();
  d["neighbor_builds"] = snapshot.neighbor_builds;
  d["removed_total"] = snapshot.removed_total;
  py::dict stages;
  for (const auto& [name, seconds] : snapshot.stages) stages[py::str(name)] = seconds;
  d["stage_seconds"] = stages;
  return d;
}

/// A value of the simulation read under the lock.
template <class Read>
auto read(SimulationHandle& handle, Read&& value) {
  return locked(handle, [&](SimulationHandle& h) {
    return std::visit([&](const auto& simulation) { return value(*simulation); }, h.simulation());
  });
}

}  // namespace

void bind_simulation(py::module_& module) {
  py::class_<SimulationHandle>(module, "Simulation",
                               "A simulation of a scene (docs/python.md): step it, run it, read its fields.")
      .def(py::init([](const py::object& scene) {
             SceneSource source = scene_argument(scene);
             const py::gil_scoped_release release;
             return std::make_unique<SimulationHandle>(std::move(source));
           }),
           py::arg("scene"), "From a Scene, a dict with a scene file's keys, or a scene file's path.")
      .def_property_readonly("scene", [](const SimulationHandle& h) { return h.source(); })
      .def_property_readonly("dimension", [](const SimulationHandle& h) { return h.source().scene.dimension; })
      .def_property_readonly(
          "time", [](SimulationHandle& h) { return read(h, [](const auto& s) { return s.time(); }); },
          "Simulated time, s.")
      .def_property_readonly("step_count",
                             [](SimulationHandle& h) { return read(h, [](const auto& s) { return s.step_count(); }); })
      .def_property_readonly(
          "particle_count", [](SimulationHandle& h) { return read(h, [](const auto& s) { return s.fluid().size(); }); })
      .def_property_readonly(
          "max_speed", [](SimulationHandle& h) { return read(h, [](const auto& s) { return double(s.max_speed()); }); },
          "The fluid's largest speed, m/s, as the next time step reads it.")
      .def_property_readonly(
          "smoothing_length",
          [](SimulationHandle& h) { return read(h, [](const auto& s) { return double(s.smoothing_length()); }); })
      .def_property_readonly(
          "rest_density",
          [](SimulationHandle& h) { return read(h, [](const auto& s) { return double(s.rest_density()); }); })
      .def_property_readonly("gravity",
                             [](SimulationHandle& h) {
                               return read(h, [](const auto& s) {
                                 std::vector<double> g;
                                 for (const Real component : s.gravity()) g.push_back(component);
                                 return g;
                               });
                             })
      .def_property_readonly("field_names", &field_names, "The fluid's fields, in creation order.")
      .def("field", &field_view, py::arg("name"),
           "A read-only NumPy view of a field, without copying: an array for a scalar or index field, a tuple of "
           "one array per component for a vector field. It shows the fluid's arrays as they are now, in the "
           "current particle order (docs/python.md, \"Views\").")
      .def_property_readonly(
          "fields",
          [](SimulationHandle& h) {
            py::dict views;
            for (const py::handle name : field_names(h)) views[name] = field_view(h, py::cast<std::string>(name));
            return views;
          },
          "Every field by name, as field() gives it.")
      .def(
          "set_fields", [](SimulationHandle& h, const py::kwargs& fields) { set_start_fields(h, fields); },
          "Before the first step: sets fields (name=values; a vector field as D rows of N or N rows of D) and starts "
          "the scheme again from them (neighbour search, densities, pressures, accelerations).")
      .def(
          "step",
          [](SimulationHandle& h) { return report_dict(locked(h, [](SimulationHandle& s) { return s.step(); })); },
          "One adaptive time step; returns its dt, the limit that bound it and what it did.")
      .def(
          "run",
          [](SimulationHandle& h, std::optional<double> until) {
            const double end = until.value_or(h.source().scene.time.end);
            if (!std::isfinite(end)) throw py::value_error("run: until must be a finite time in s");
            const std::uint64_t first = read(h, [](const auto& s) { return s.step_count(); });
            while (!locked(h, [&](SimulationHandle& s) { return s.run_for(end, signal_check_interval); }))
              if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            return read(h, [](const auto& s) { return s.step_count(); }) - first;
          },
          py::arg("until") = py::none(),
          "Steps until the simulated time reaches `until` (default: the scene's end time); returns the steps taken.")
      .def_property_readonly(
          "statistics",
          [](SimulationHandle& h) {
            return statistics_dict(locked(h, [](SimulationHandle& s) {
              return std::visit(
                  [&](const auto& simulation) {
                    StatisticsSnapshot snapshot{
                        s.statistics(), simulation->neighbor_builds(), simulation->removed_total(), {}};
                    for (const StageTime& stage : simulation->pipeline().times())
                      snapshot.stages.emplace_back(std::string(stage.name), stage.seconds);
                    return snapshot;
                  },
                  s.simulation());
            }));
          },
          "Steps, particle-steps, wall time, how often each time-step limit bound, pressure solves, neighbour "
          "builds, removed particles and each stage's seconds, since the simulation was built or restored.")
      .def(
          "probes",
          [](SimulationHandle& h) {
            const std::vector<double> values =
                read(h, [&](const auto& s) { return read_probes(s, h.source().scene.probes); });
            py::dict readings;
            for (std::size_t k = 0; k < values.size(); ++k)
              readings[py::str(h.source().scene.probes[k].name)] = values[k];
            return readings;
          },
          "The scene's probes read now, by name: pressures in Pa, water heights in m.")
      .def(
          "write_checkpoint",
          [](SimulationHandle& h, const std::filesystem::path& file) {
            locked(h, [&](SimulationHandle& s) { s.write_checkpoint(file); });
          },
          py::arg("path"), "Writes the state to an HDF5 checkpoint, atomically (docs/output.md, \"Checkpoints\").")
      .def(
          "restore_checkpoint",
          [](SimulationHandle& h, const std::filesystem::path& file) {
            locked(h, [&](SimulationHandle& s) { s.restore_checkpoint(file); });
          },
          py::arg("path"),
          "Continues from a checkpoint of this scene (written by write_checkpoint, or tide run's checkpoint.h5 "
          "for a scene file), bit for bit; CheckpointError for one of another scene, precision or dimension.");
}

}  // namespace tide::python
