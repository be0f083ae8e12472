#pragma once

// The constants of the surface-tension passes, from the scene (docs/multiphase.md).

#include <memory>

#include "passes/surface_tension.hpp"
#include "tide/core/kernels/kernel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/scene.hpp"
#include "tide/solvers/particle_fields.hpp"
#include "tide/solvers/phases.hpp"

namespace tide::setup {

/// σ per unit pair strength of the Tartakovsky & Meakin 2005 force on the scene's lattice: the
/// tension of a flat free surface of a filled lattice, half the work per unit area (2D: length)
/// to pull two half-lattices apart, −(n/4) Σ_k |k_y| φ(|k|), n = 1/Δx^D, over the lattice offsets
/// k within the support, φ the pair potential of a unit-strength force.
template <int D>
Real pairwise_tension_per_strength(Real spacing, Real support_radius);

/// The settings of the scene's surface-tension model. `phases` is null for a single fluid; then
/// `rest_density` and `wall_volume` describe it.
template <int D>
passes::SurfaceTensionSettings surface_tension_settings(const scene::Scene& scene, const AnyKernel<D>& kernel,
                                                        const Phases* phases, Real rest_density, Real wall_volume);

/// What a scheme keeps of the scene's surface tension: the settings of its model (null without
/// tension) and the capillary time-step limit of the csf and pairwise models (0 otherwise).
struct SchemeSurfaceTension {
  std::unique_ptr<const passes::SurfaceTensionSettings> settings;
  Real capillary_limit = 0;
};

/// The scheme's surface tension (surface_tension_settings, with the particles' mass for the wall
/// volume), adding to `fluid` the colour-gradient field that the csf and akinci models write.
template <int D>
SchemeSurfaceTension make_surface_tension(const scene::Scene& scene, const AnyKernel<D>& kernel, const Phases* phases,
                                          Real rest_density, Real particle_mass, ParticleSet<D>& fluid,
                                          FluidFields<D>& fields);

}  // namespace tide::setup
