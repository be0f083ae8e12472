#pragma once

// The density of a free-surface particle under continuity density with clamped pressure.

#include <algorithm>
#include <span>

#include "tide/core/parallel.hpp"
#include "tide/core/types.hpp"

namespace tide::passes {

/// ρ_i = max(ρ_i, ρ_surface) for every particle with ∇·r_i below `surface_divergence` (a
/// free-surface particle, Lind et al. 2012). The free surface is where p = 0 (the dynamic
/// condition WCSPH meets by clamping p = max(p(ρ), 0)), so a surface particle's density is the
/// equation of state's at that pressure, ρ0, or more where it is compressed. Integrated by the
/// continuity equation, the density of a particle in a stretching jet or a splash keeps falling
/// (Dρ/dt = −ρ ∇·v with nothing in the clamped pressure to resist), a memory of expansion that
/// no longer means pressure, until it leaves the stability band. SPHinXsys re-initialises the
/// density of a free-surface flow in the same way, ρ = max(ρ_summed, ρ0)
/// (DensitySummationFreeSurface, with the Riemann WCSPH of Zhang, Hu & Adams 2017); here only
/// at the surface and on the integrated density. Particles in the bulk keep theirs, so a real
/// rarefaction or blow-up there still meets the stability band.
inline void hold_free_surface_density(std::span<const Real> divergence, Real surface_divergence, Real surface_density,
                                      std::span<Real> density) {
  for_each_particle(density.size(), [&](std::size_t i) {
    if (divergence[i] < surface_divergence) density[i] = std::max(density[i], surface_density);
  });
}

}  // namespace tide::passes
