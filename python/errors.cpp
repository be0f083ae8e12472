#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "tide/core/scene_error.hpp"
#include "tide/io/checkpoint_file.hpp"
#include "tide/solvers/instability.hpp"

namespace py = pybind11;

namespace tide::python {

void bind_errors(py::module_& module) {
  // A scene that is not valid: the message names the file (or the dict's name) and the JSON key path.
  py::register_exception<scene::SceneError>(module, "SceneError", PyExc_ValueError);
  // A run that left its bounds: particle, field, value, step and time, and what bound the last step.
  py::register_exception<InstabilityError>(module, "InstabilityError", PyExc_RuntimeError);
  // A checkpoint written for another scene, precision, dimension or format version.
  py::register_exception<io::CheckpointMismatch>(module, "CheckpointError", PyExc_RuntimeError);
}

}  // namespace tide::python
