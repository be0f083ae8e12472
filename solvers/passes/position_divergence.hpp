#pragma once

// The divergence of position, the free-surface marker of particle shifting and of the
// free-surface density of continuity WCSPH.

#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "neighbor_walk.hpp"
#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

namespace detail {

/// Calls add(V_j, x_ij, r²) for every fluid (j ≠ i) and contact neighbour of fluid particle i,
/// V_j = m_j/ρ_j; `contact_volumes` holds each contact's masses and densities.
template <int D, class Add>
void for_each_volume_neighbor(
    std::size_t i, const FluidNeighbors<D>& neighbors, std::span<const Real> mass, std::span<const Real> density,
    const std::vector<std::pair<std::span<const Real>, std::span<const Real>>>& contact_volumes, Add&& add) {
  neighbors.fluid_pairs([&](Index j, const Vector<D>& x_ij, Real r2) {
    if (j != i) add(mass[j] / density[j], x_ij, r2);
  });
  neighbors.contacts([&](const ContactNeighbors<D>& contact) {
    const auto& [contact_mass, contact_density] = contact_volumes[contact.number()];
    contact.pairs(
        [&](Index b, const Vector<D>& x_ib, Real r2) { add(contact_mass[b] / contact_density[b], x_ib, r2); });
  });
}

/// The masses and densities of every contact, for for_each_volume_neighbor.
template <int D>
std::vector<std::pair<std::span<const Real>, std::span<const Real>>> contact_volumes(
    const Interactions<D>& interactions) {
  std::vector<std::pair<std::span<const Real>, std::span<const Real>>> volumes;
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    volumes.emplace_back(contact.particles()[contact.fields().mass], contact.particles()[contact.fields().density]);
  }
  return volumes;
}

}  // namespace detail

/// ∇·r_i = −Σ_j V_j x_ij·∇W_ij of fluid particle i over its fluid and contact neighbours
/// (V_j = m_j/ρ_j; `contact_volumes` as for for_each_volume_neighbor).
template <int D>
Real position_divergence_of(
    const RuntimeKernel<D>& kernel, std::size_t i, const FluidNeighbors<D>& neighbors, std::span<const Real> mass,
    std::span<const Real> density,
    const std::vector<std::pair<std::span<const Real>, std::span<const Real>>>& contact_volumes) {
  Real sum = 0;
  detail::for_each_volume_neighbor<D>(i, neighbors, mass, density, contact_volumes,
                                      [&](Real volume, const Vector<D>& x_ij, Real r2) {
                                        sum -= volume * x_ij.dot(kernel.gradient(x_ij, std::sqrt(r2)));
                                      });
  return sum;
}

/// The divergence of position ∇·r_i = −Σ_j V_j x_ij·∇W_ij over fluid and contact neighbours
/// (V_j = m_j/ρ_j): the dimension inside the fluid, smaller where the support is partly empty,
/// which marks the free surface (Lee et al. 2008; Lind et al. 2012 take ∇·r < 1.5 in 2D).
template <int D>
void position_divergence(const RuntimeKernel<D>& kernel, const ParticleSet<D>& fluid, const FluidFields<D>& f,
                         const Interactions<D>& interactions, std::span<Real> divergence) {
  const auto mass = fluid[f.mass];
  const auto density = fluid[f.density];
  const auto volumes = detail::contact_volumes(interactions);
  for_each_fluid_particle<D>(interactions, fluid[f.position], ScalarOutput{divergence},
                             [&](std::size_t i, const FluidNeighbors<D>& neighbors) {
                               return position_divergence_of<D>(kernel, i, neighbors, mass, density, volumes);
                             });
}

}  // namespace tide::passes
