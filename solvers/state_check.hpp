#pragma once

// The end-of-step check every scheme runs: the largest speed and acceleration (for the next
// time step), and the first particle whose state leaves the bounds of a meaningful run.

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "tide/core/particle_set.hpp"
#include "tide/solvers/particle_fields.hpp"
#include "tide/solvers/phases.hpp"

namespace tide {

struct StateLimits {
  Real min_density = 0;  // 0: no lower bound (summation density is naturally low at a free surface)
  Real max_density = 0;
  std::string density_band;  // the band in words, for the message
  Real max_speed = 0;
  std::string speed_bound;            // the speed bound in words, for the message
  std::function<std::string()> note;  // when set, a sentence added to the message (asked only on failure)
  // Several fluids: the density bounds are on ρ_i / ρ0 of the particle's phase.
  std::span<const Index> phase;
  std::vector<Real> inverse_rest_density;  // by phase
};

struct StateMaxima {
  Real speed = 0;
  Real acceleration = 0;
};

/// Throws InstabilityError for the lowest-index fluid particle with a non-finite position,
/// velocity, acceleration or density, a density outside the limits or a speed above them;
/// otherwise returns the maxima. A deterministic reduction, so any thread count gives the same.
/// Several fluids: turns the density bounds of `limits`, set for the reference rest density
/// `rest_density`, into the same bounds on ρ_i / ρ0 of each particle's phase.
void bound_density_by_phase(StateLimits& limits, Real rest_density, const Phases& phases, std::span<const Index> phase);

template <int D>
StateMaxima check_fluid_state(const ParticleSet<D>& fluid, const FluidFields<D>& f, const StateLimits& limits,
                              std::uint64_t step, double time);

}  // namespace tide
