#pragma once

// Density by kernel summation over fluid and wall particles, fused with what a scheme derives
// from it per particle (WCSPH: the equation of state).

#include <cmath>

#include "tide/core/parallel.hpp"
#include "tide/solvers/fluid_wall_neighbors.hpp"
#include "tide/solvers/particle_fields.hpp"

namespace tide::passes {

/// ρ_i = Σ_j m_j W_ij over fluid and wall neighbours (Monaghan 1992, eq. 2.7), then
/// then_each(i, ρ_i), which may write particle i's other fields. With `NumberDensity` (several
/// fluids of different density): ρ_i = m_i Σ_j W_ij, the particle's own mass times its number
/// density (Hu & Adams 2006, eq. 4), so the density is sharp across an interface instead of
/// smeared over a kernel support. The pairs come from FluidWallNeighbors::walk_fluid_pairs, so
/// after an update that left the listing to it, this pass also lists the neighbours.
template <int D, bool NumberDensity = false, class Kernel, class ThenEach>
void density_summation(const Kernel& kernel, ParticleSet<D>& fluid, const FluidFields<D>& f,
                       FluidWallNeighbors<D>& neighbors, const ParticleSet<D>& walls, const WallFields<D>& w,
                       ThenEach&& then_each) {
  const auto x = std::as_const(fluid)[f.position];
  const auto mass = std::as_const(fluid)[f.mass];
  const auto wall_x = walls[w.position];
  const auto wall_mass = walls[w.mass];
  auto density = fluid[f.density];
  // The fluid sum is kept in density[i] until the wall sum goes on from it.
  const auto add_sum = [&](Real sum, const std::span<const Real> neighbor_mass, const auto& runs) {
    runs([&](const NeighborRun<D>& run) {
      if constexpr (NumberDensity) {
        accumulate(run, sum, [&](int k) { return kernel.value(std::sqrt(run.r2[k])); });
      } else {
        accumulate(run, sum, [&](int k) { return neighbor_mass[run.index[k]] * kernel.value(std::sqrt(run.r2[k])); });
      }
    });
    return sum;
  };
  neighbors.walk_fluid_pairs(
      x, wall_x, [&](std::size_t i, const auto& runs) { density[i] = add_sum(0, mass, runs); },
      [&](std::size_t i, const auto& runs) {
        Real sum = add_sum(density[i], wall_mass, runs);
        if constexpr (NumberDensity) sum *= mass[i];
        density[i] = sum;
        then_each(i, sum);
      });
}

}  // namespace tide::passes
