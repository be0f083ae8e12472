// The tidesph Python module (docs/python.md): scenes, simulations, their fields as NumPy arrays,
// checkpoints, and the files a run writes.

#include "bindings.hpp"

PYBIND11_MODULE(tidesph, module) {
  module.doc() = "TideSPH: smoothed-particle hydrodynamics from Python (docs/python.md)";
  tide::python::bind_errors(module);
  tide::python::bind_build(module);
  tide::python::bind_scene(module);
  tide::python::bind_simulation(module);
  tide::python::bind_run_files(module);
}
