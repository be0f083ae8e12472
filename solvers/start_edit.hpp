#pragma once

// What every scheme's Simulation::edit_start does before it starts again from the edited fields.

#include <cstdint>

#include "tide/core/function_ref.hpp"
#include "tide/core/particle_set.hpp"

namespace tide::setup {

/// Runs `edit` on `fluid`: std::logic_error when `step_count` is not 0 (the start is behind) or
/// when `edit` changed the particle count (a caller's error that leaves the scheme's other arrays
/// at the old count: the simulation is not to be stepped after it).
template <int D>
void edit_start_fields(std::uint64_t step_count, ParticleSet<D>& fluid, FunctionRef<void(ParticleSet<D>&)> edit);

}  // namespace tide::setup
