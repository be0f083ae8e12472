#pragma once

// Runs a call on a SimulationHandle under its lock with the GIL released: the lock is only ever
// waited for without the GIL, and what runs under it never touches Python, so a thread stepping
// one simulation and another reading it can never wait for each other in a circle.

#include <mutex>
#include <utility>

#include <pybind11/pybind11.h>

#include "simulation_handle.hpp"

namespace tide::python {

template <class Call>
auto locked(SimulationHandle& handle, Call&& call) {
  const pybind11::gil_scoped_release release;
  const std::lock_guard lock(handle.mutex());
  return std::forward<Call>(call)(handle);
}

}  // namespace tide::python
