#pragma once

// The fluid's fields as NumPy arrays: zero-copy, read-only views of the structure-of-arrays
// storage that keep the simulation alive, and the copy that sets the starting fields.

#include <string>

#include <pybind11/pybind11.h>

#include "simulation_handle.hpp"

namespace tide::python {

/// The field `name` of the fluid: a 1-D array (N) for a scalar or index field, a tuple of D such
/// arrays (one per component) for a vector field. KeyError names the field and lists the fields
/// there are.
pybind11::object field_view(SimulationHandle& handle, const std::string& name);

/// Names of the fluid's fields, in creation order.
pybind11::list field_names(SimulationHandle& handle);

/// Sets the starting fields (`fields`: name → values, a scalar field's as N numbers, a vector
/// field's as D rows of N or N rows of D) and starts the simulation again from them
/// (Simulation::edit_start). Every value is checked before any is set.
void set_start_fields(SimulationHandle& handle, const pybind11::dict& fields);

}  // namespace tide::python
