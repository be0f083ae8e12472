#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "scene_argument.hpp"
#include "tide/solvers/simulation.hpp"

namespace py = pybind11;

namespace tide::python {

SceneSource scene_from_dict(const py::dict& scene, const std::string& name) {
  // The same checks as a file's: the dict becomes JSON text for the scene reader, keys sorted so
  // that equal dicts give equal text (and checkpoints of equal hash); NumPy values become lists.
  const py::module_ json = py::module_::import("json");
  const py::cpp_function plain([](const py::object& value) -> py::object {
    if (py::hasattr(value, "tolist")) return value.attr("tolist")();
    throw py::type_error("a scene value of type " + std::string(py::str(value.get_type().attr("__name__"))) +
                         " is not JSON");
  });
  const std::string text = py::str(
      json.attr("dumps")(scene, py::arg("sort_keys") = true, py::arg("allow_nan") = false, py::arg("default") = plain));
  return scene_from_text(text, name);
}

SceneSource scene_argument(const py::object& scene) {
  if (py::isinstance<SceneSource>(scene)) return scene.cast<SceneSource>();
  if (py::isinstance<py::dict>(scene)) return scene_from_dict(scene, "scene dict");
  return scene_from_file(py::str(py::module_::import("os").attr("fspath")(scene)).cast<std::string>());
}

void bind_scene(py::module_& module) {
  py::class_<SceneSource>(module, "Scene", "A checked scene (docs/scenes.md), from a file or a dict.")
      .def_property_readonly(
          "source", [](const SceneSource& s) { return s.scene.source; },
          "The file it came from, or the name given to its dict.")
      .def_property_readonly("dimension", [](const SceneSource& s) { return s.scene.dimension; })
      .def_property_readonly("scheme",
                             [](const SceneSource& s) { return std::string(scheme_name(s.scene.solver.scheme)); })
      .def_property_readonly("particle_spacing", [](const SceneSource& s) { return s.scene.particle_spacing; })
      .def_property_readonly("start_time", [](const SceneSource& s) { return s.scene.time.start; })
      .def_property_readonly("end_time", [](const SceneSource& s) { return s.scene.time.end; })
      .def_property_readonly("probe_names",
                             [](const SceneSource& s) {
                               py::list names;
                               for (const scene::Probe& probe : s.scene.probes) names.append(probe.name);
                               return names;
                             })
      .def("__repr__", [](const SceneSource& s) {
        return "<tidesph.Scene " + s.scene.source + ": " + std::to_string(s.scene.dimension) + "D " +
               std::string(scheme_name(s.scene.solver.scheme)) + ">";
      });
  module.def(
      "load_scene", [](const py::object& path) { return scene_argument(path); }, py::arg("path"),
      "Reads and checks a scene file; SceneError names the file, the key path and what was expected.");
  module.def("scene_from_dict", &scene_from_dict, py::arg("scene"), py::arg("name") = "scene dict",
             "Checks a scene given as a dict with the keys of a scene file; SceneError names `name` and the key "
             "path, e.g. \"scene dict: /solver/cfl: expected a number > 0, got \\\"fast\\\"\".");
}

}  // namespace tide::python
