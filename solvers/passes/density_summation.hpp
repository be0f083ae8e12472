#pragma once

// Density by kernel summation over fluid and contact particles, fused with what a scheme derives
// from it per particle (WCSPH: the equation of state).

#include <span>
#include <vector>

#include "tide/core/kernels/runtime_kernel.hpp"
#include "tide/core/parallel.hpp"
#include "tide/neighbor/neighbor_run.hpp"
#include "tide/solvers/interactions.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// ρ_i = Σ_j m_j W_ij over fluid and contact neighbours (Monaghan 1992, eq. 2.7), then
/// then_each(i, ρ_i), which may write particle i's other fields. With `NumberDensity` (several
/// fluids of different density): ρ_i = m_i Σ_j W_ij, the particle's own mass times its number
/// density (Hu & Adams 2006, eq. 4), so the density is sharp across an interface instead of
/// smeared over a kernel support. The pairs come from Interactions::walk_fluid_pairs, so after an
/// update that left the listing to it, this pass also lists the neighbours; that walk visits the
/// fluid and each contact one after the other, so the sum so far is kept in density[i] between
/// them, and the last contact's visit finishes it.
template <int D, bool NumberDensity = false, class ThenEach>
void density_summation(const RuntimeKernel<D>& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                       Interactions<D>& interactions, ThenEach&& then_each) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  auto density = fluid[f.density];
  const std::size_t contact_count = interactions.contact_count();
  const auto add_sum = [&](Real sum, const std::span<const Real> neighbor_mass, const auto& runs) {
    runs([&](const NeighborRun<D>& run) {
      kernel.visit([&](const auto& w) {
        if constexpr (NumberDensity) {
          accumulate(run, sum, [&](int k) { return w.value(std::sqrt(run.r2[k])); });
        } else {
          accumulate(run, sum, [&](int k) { return neighbor_mass[run.index[k]] * w.value(std::sqrt(run.r2[k])); });
        }
      });
    });
    return sum;
  };
  const auto finish = [&](std::size_t i, Real sum) {
    if constexpr (NumberDensity) sum *= mass[i];
    density[i] = sum;
    then_each(i, sum);
  };
  std::vector<std::span<const Real>> contact_mass;
  for (std::size_t k = 0; k < interactions.contact_count(); ++k) {
    const Contact<D>& contact = interactions.contact(k);
    contact_mass.push_back(contact.particles()[contact.fields().mass]);
  }
  interactions.walk_fluid_pairs(
      x,
      [&](std::size_t i, const auto& runs) {
        const Real sum = add_sum(0, mass, runs);
        if (contact_count == 0) {
          finish(i, sum);
        } else {
          density[i] = sum;
        }
      },
      [&](std::size_t i, std::size_t k, const auto& runs) {
        const Real sum = add_sum(density[i], contact_mass[k], runs);
        if (k + 1 == contact_count) {
          finish(i, sum);
        } else {
          density[i] = sum;
        }
      });
}

}  // namespace tide::passes
