#pragma once

// Fickian particle shifting: small position corrections down the gradient of particle
// concentration that keep the distribution uniform, projected at a free surface so that the
// surface does not diffuse.

#include <algorithm>
#include <cmath>
#include <span>

#include "position_divergence.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/parallel.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

struct ShiftingSettings {
  Real diffusion = 0;            // D = 4 h |v|max Δt, the shift per unit concentration gradient
  Real lattice_kernel = 0;       // W(Δx), the kernel at one particle spacing
  Real surface_divergence = 0;   // ∇·r below this: a free-surface particle
  Real isolated_divergence = 0;  // ∇·r below this: a splash particle (not shifted)
};

/// Writes the shift of every fluid particle into `shift`:
///   δr_i = −D_i Σ_j [1 + R (W_ij/W(Δx))^n] V_j ∇W_ij,  R = 0.2, n = 4
/// (Lind, Xu, Stansby & Rogers 2012, eq. 13 with the anti-pairing term of their eq. 14), over
/// fluid and contact neighbours, so that a particle moves down the gradient of particle
/// concentration and pairs closer than Δx repel. D is that of Sun et al. 2017 (eq. 9),
/// CFL·Ma·(2h)² = 4 h U Δt, with U the current maximum speed: the shift is a diffusion of 4 h U
/// per unit time whatever the time step, and a fluid coming to rest is no longer stirred. (The
/// particle's own speed instead of U, as in Skillen et al. 2013, leaves the stagnation points of
/// a vortex, where the lattice pairs first, unshifted.)
/// Near a free surface the concentration gradient is that of the surface itself, and a full
/// shift would push the fluid out through it: a particle with a free-surface particle (∇·r below
/// the threshold, itself included) within its support keeps only the tangential part of its shift,
/// (I − n nᵀ) δr, with n = −Σ V_j ∇W_ij / |…| (Lind et al. 2012, Sec. 3.3); a splash particle is
/// not shifted.
template <int D>
void particle_shifting(const RuntimeKernel<D>& kernel, const ShiftingSettings& settings, const ParticleSet<D>& fluid,
                       const FluidFields<D>& f, const Interactions<D>& interactions, std::span<const Real> divergence,
                       VectorView<D> shift) {
  constexpr Real repulsion = Real(0.2);  // R
  const auto mass = fluid[f.mass];
  const auto density = fluid[f.density];
  const auto volumes = detail::contact_volumes(interactions);
  for_each_fluid_particle<D>(
      interactions, fluid[f.position], VectorOutput<D>{shift}, [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
        if (divergence[i] < settings.isolated_divergence) return Vector<D>(Vector<D>::Zero());
        Vector<D> concentration_gradient = Vector<D>::Zero();  // Σ V_j ∇W_ij
        Vector<D> weighted_gradient = Vector<D>::Zero();       // Σ [1 + R (W/W(Δx))⁴] V_j ∇W_ij
        detail::for_each_volume_neighbor<D>(i, neighbors, mass, density, volumes,
                                            [&](Real volume, const Vector<D>& x_ij, Real r2) {
                                              const Real r = std::sqrt(r2);
                                              const Vector<D> grad_w = volume * kernel.gradient(x_ij, r);
                                              const Real ratio = kernel.value(r) / settings.lattice_kernel;
                                              const Real ratio2 = ratio * ratio;
                                              concentration_gradient += grad_w;
                                              weighted_gradient += (1 + repulsion * ratio2 * ratio2) * grad_w;
                                            });
        bool near_surface = divergence[i] < settings.surface_divergence;
        neighbors.fluid_pairs([&](Index j, const Vector<D>&, Real) {
          near_surface = near_surface || divergence[j] < settings.surface_divergence;
        });
        Vector<D> delta = -settings.diffusion * weighted_gradient;
        const Real norm = concentration_gradient.norm();
        if (near_surface && norm > 0) {
          const Vector<D> normal = -concentration_gradient / norm;
          delta -= delta.dot(normal) * normal;
        }
        return delta;
      });
}

/// Moves every fluid particle by its shift: position_divergence, then particle_shifting with the
/// diffusion 4 h U Δt for the fastest particle speed U (Sun et al. 2017, eq. 9), at most h²/2, the
/// Fourier-stability limit of one explicit diffusion step of the concentration (Lind et al. 2012,
/// Sec. 3.2): a weakly compressible step keeps far below it, but the time step of the
/// incompressible schemes, CFL h / U, would give 4 CFL h² and overshoot the uniform distribution.
/// The anti-pairing term is scaled by the kernel at one particle spacing, and the free-surface
/// thresholds are those of Lind et al. 2012 (∇·r < D − 0.5; splash below D/2).
template <int D>
void shift_particles(const RuntimeKernel<D>& kernel, Real spacing, Real smoothing_length, Real max_speed, Real dt,
                     ParticleSet<D>& fluid, const FluidFields<D>& f, const Interactions<D>& interactions) {
  const Real diffusion = std::min(4 * smoothing_length * max_speed * dt, smoothing_length * smoothing_length / 2);
  const ShiftingSettings settings{diffusion, kernel.value(spacing), Real(D) - Real(0.5), Real(D) / 2};
  position_divergence<D>(kernel, fluid, f, interactions, fluid[f.position_divergence]);
  particle_shifting<D>(kernel, settings, fluid, f, interactions, std::as_const(fluid)[f.position_divergence],
                       fluid[f.shift]);
  auto x = fluid[f.position];
  const auto shift = std::as_const(fluid)[f.shift];
  for_each_particle(fluid.size(), [&](std::size_t i) { x.set(i, x[i] + shift[i]); });
}

}  // namespace tide::passes
