#pragma once

#include <string>

#include "tide/core/particle_set.hpp"
#include "tide/core/state_archive.hpp"

namespace tide {

/// Puts every field of `set`, its size and its next id under `prefix` ("<prefix>/<field>"; a
/// vector field's components one after the other).
template <int D>
void save_particles(StateArchive& archive, const std::string& prefix, const ParticleSet<D>& set);

/// Gives `set` the size, next id and every field save_particles put under `prefix`: `set` has the
/// same fields (built from the same scene); std::runtime_error naming the entry when one is
/// missing or has another length.
template <int D>
void restore_particles(const StateArchive& archive, const std::string& prefix, ParticleSet<D>& set);

}  // namespace tide
