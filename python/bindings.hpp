#pragma once

// The parts of the tidesph module (module.cpp), each in its own file.

#include <pybind11/pybind11.h>

namespace tide::python {

/// tidesph.SceneError, InstabilityError, CheckpointError: the C++ errors as Python exceptions.
void bind_errors(pybind11::module_& module);
/// tidesph.Scene, load_scene, scene_from_dict.
void bind_scene(pybind11::module_& module);
/// tidesph.Simulation.
void bind_simulation(pybind11::module_& module);
/// tidesph.frame_files, read_frame, read_series: what a run wrote.
void bind_run_files(pybind11::module_& module);
/// tidesph.threads, set_threads, precision, version.
void bind_build(pybind11::module_& module);

}  // namespace tide::python
