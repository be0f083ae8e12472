#pragma once

// The density of a free-surface particle under continuity density with clamped pressure.

#include <span>
#include <utility>

#include "position_divergence.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

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
/// The held densities go through `scratch` (a Real per fluid particle), so that every ∇·r sees
/// the densities from before the pass. Only a particle below ρ_surface can change, so only those
/// walk their neighbours for ∇·r: under gravity, those near the surface.
template <int D>
void hold_free_surface_density(const RuntimeKernel<D>& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                               const Interactions<D>& interactions, Real surface_divergence, Real surface_density,
                               std::span<Real> scratch) {
  const auto mass = std::as_const(fluid)[f.mass];
  const auto density = std::as_const(fluid)[f.density];
  const auto volumes = detail::contact_volumes(interactions);
  for_each_fluid_particle<D>(interactions, std::as_const(fluid)[f.position], ScalarOutput{scratch},
                             [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
                               if (density[i] >= surface_density) return density[i];
                               const Real divergence =
                                   position_divergence_of<D>(kernel, i, neighbors, mass, density, volumes);
                               return divergence < surface_divergence ? surface_density : density[i];
                             });
  auto held = fluid[f.density];
  for_each_particle(fluid.size(), [&](std::size_t i) { held[i] = scratch[i]; });
}

}  // namespace tide::passes
